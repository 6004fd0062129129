#include "src/pipeline/cooling.hpp"

namespace cg::pipeline {

void validate_cooling(const config::CoolingConfig& cooling, const blade::BladeModel& model) {
  try {
    features::validate_passages(model, cooling.passages);
  } catch (const features::PassageInputError& e) {
    throw config::cooling_error(e);
  }
}

features::PassagesResult apply_cooling(const config::CoolingConfig& cooling, const blade::BladeModel& model,
                                       const brep::NamedShape& blade) {
  try {
    return features::build_passages(model, blade, cooling.passages);
  } catch (const features::PassageInputError& e) {
    throw config::cooling_error(e);
  }
}

}  // namespace cg::pipeline
