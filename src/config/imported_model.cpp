#include "src/config/imported_model.hpp"

#include "src/blade_import/fidelity.hpp"
#include "src/blade_import/slice_blade.hpp"
#include "src/blade_import/table_blade.hpp"
#include "src/cad_import/cad_blade.hpp"

namespace cg::config {
namespace {

// The blade as imported: the geomTurbo file's as read, or the section tables' outlines (or a STEP /
// IGES blade's cuts) split into sides, with the config's flow path as the channel.
std::shared_ptr<const blade_import::ImportedBlade> imported_blade(const Config& config) {
  const BladeImport& im = *config.blade_import;
  if (im.blade) return im.blade;
  using blade_import::RowKind;
  std::vector<Eigen::Vector2d> hub, casing;
  RowKind kind = RowKind::Annular;
  if (const auto* m = std::get_if<blade::MeridionalFlowPath>(&config.blade.flow_path)) {
    hub = m->net.hub;
    casing = m->net.casing;
  } else {
    kind = RowKind::Cascade;
    const double span = std::get<blade::StraightFlowPath>(config.blade.flow_path).span;
    hub = {{-1e4, 0}, {1e4, 0}};
    casing = {{-1e4, span}, {1e4, span}};
  }
  if (im.format == "step" || im.format == "iges") {
    cad_import::CadCutOptions o;
    o.cuts = im.cuts;
    o.tolerance = im.options.tolerance;
    o.edges = im.options.edges;
    const auto* m = std::get_if<blade::MeridionalFlowPath>(&config.blade.flow_path);
    return std::make_shared<const blade_import::ImportedBlade>(cad_import::read_cad_blade(
        im.files[0], im.format == "step" ? cad_import::CadFormat::Step : cad_import::CadFormat::Iges, kind, hub, casing,
        m ? &m->net : nullptr, o));
  }
  return std::make_shared<const blade_import::ImportedBlade>(blade_import::blade_from_tables(im.tables, kind, hub, casing, im.options.edges));
}

}  // namespace

blade::BladeModel build_imported_model(const Config& config, ProgressSink* progress) {
  const BladeImport& im = *config.blade_import;
  report_progress(progress, 0.2, "blade.import: cutting the blade at the streamlines");
  check_cancel(progress, "blade.import");
  std::shared_ptr<const blade_import::ImportedBlade> input;
  blade_import::SlicedBlade sliced;
  try {
    input = imported_blade(config);
    const auto* m = std::get_if<blade::MeridionalFlowPath>(&config.blade.flow_path);
    sliced = blade_import::slice_blade(*input, im.options, config.blade.options, im.blade || !m ? nullptr : &m->net);
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
    model.imported = blade_import::measure_fidelity(*input, sliced, model, im.options.tolerance);
  } catch (const InvalidGeometry& e) {
    throw ConfigError(std::string("blade.import.tolerance: ") + e.what());
  }
  model.imported->format = im.format;
  return model;
}

}  // namespace cg::config
