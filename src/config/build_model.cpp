// build_model: the blade model of a parsed config, each part checked on its own first so that a failure
// names the part of the config it comes from (apart from config.cpp's reading, which needs no model).
#include "src/blade/meridional_net.hpp"
#include "src/blade/section.hpp"
#include "src/config/config.hpp"
#include "src/config/imported_model.hpp"
#include "src/config/point_checks.hpp"

namespace cg::config {

blade::BladeModel build_model(const Config& config, ProgressSink* progress) {
  const blade::BladeDefinition& def = config.blade;
  // Check the parts separately first, so a failure names the part of the config it comes from.
  if (const auto* m = std::get_if<blade::MeridionalFlowPath>(&def.flow_path)) {
    try {
      blade::MeridionalNet net(m->net);
    } catch (const InvalidGeometry& e) {
      throw ConfigError(std::string("flow_path: ") + e.what());
    }
  }
  if (config.blade_import) return build_imported_model(config, progress);
  const double steps = static_cast<double>(def.sections.size() + 2);
  for (std::size_t i = 0; i < def.sections.size(); ++i) {
    const std::string name = "sections[" + std::to_string(i) + "]";
    report_progress(progress, static_cast<double>(i + 1) / steps, name);
    check_cancel(progress, name);
    const auto& shape = def.sections[i].shape;
    if (const auto* p = std::get_if<blade::PointSectionDefinition>(&shape)) {
      const PointSource source = i < config.point_sources.size() ? config.point_sources[i] : PointSource{name + ".points", p->file, {}};
      check_point_outline(*p, source);
      try {
        blade::section_from_points(*p);
      } catch (const InvalidGeometry& e) {
        throw ConfigError(source.field + ": " + e.what());
      } catch (const AlgorithmFailure& e) {  // LE/TE detection
        throw ConfigError(source.field + ": " + e.what() + "; " + le_te_index_hint(*p, source));
      }
      continue;
    }
    try {
      blade::section_from_parameters(std::get<blade::ParametricSectionDefinition>(shape));
    } catch (const InvalidGeometry& e) {
      throw ConfigError(name + ".parametric: " + e.what());
    }
  }
  report_progress(progress, (steps - 1) / steps, "blade surface");
  check_cancel(progress, "blade surface");
  try {
    return blade::build_blade(def);
  } catch (const InvalidGeometry& e) {
    throw ConfigError(std::string("blade model (flow_path + sections): ") + e.what());
  }
}

}  // namespace cg::config
