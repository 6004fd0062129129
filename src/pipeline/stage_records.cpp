#include "src/pipeline/stage_records.hpp"

namespace cg::pipeline {

const char* StageCacheUse::name(Outcome o) {
  switch (o) {
    case Outcome::kHit: return "hit";
    case Outcome::kStored: return "stored";
    case Outcome::kNotStored: return "not_stored";
  }
  return "not_stored";
}

}  // namespace cg::pipeline
