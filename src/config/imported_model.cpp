#include "src/config/imported_model.hpp"

#include "src/blade_import/fidelity.hpp"
#include "src/blade_import/slice_blade.hpp"

namespace cg::config {

blade::BladeModel build_imported_model(const Config& config, ProgressSink* progress) {
  const BladeImport& im = *config.blade_import;
  report_progress(progress, 0.2, "blade.import: cutting the blade at the streamlines");
  check_cancel(progress, "blade.import");
  blade_import::SlicedBlade sliced;
  try {
    sliced = blade_import::slice_blade(*im.blade, im.options, config.blade.options);
  } catch (const InvalidGeometry& e) {
    throw ConfigError(im.field + ": " + e.what());
  }
  report_progress(progress, 0.6, "blade surface");
  check_cancel(progress, "blade surface");
  blade::BladeModel model;
  try {
    model = blade::build_blade(sliced.definition);
  } catch (const InvalidGeometry& e) {
    throw ConfigError(im.field + ": the blade cut from it: " + e.what());
  }
  try {
    model.imported = blade_import::measure_fidelity(*im.blade, sliced, model, im.options.tolerance);
  } catch (const InvalidGeometry& e) {
    throw ConfigError(std::string("blade.import.tolerance: ") + e.what());
  }
  model.imported->format = im.format;
  return model;
}

}  // namespace cg::config
