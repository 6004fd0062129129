#pragma once
// Design checks and measures on the built (cooled) blade: thicknesses with BRepExtrema_DistShapeShape
// between the named faces of both sides, cross-sections of every passage on stream surfaces (area,
// wetted perimeter, hydraulic diameter; features/passages/span_sections.hpp), and the cavity count (every chamber must open to a coolant
// inlet: a closed cavity is a separate shell of the solid).
#include <string>
#include <vector>

#include "features/passages/core_passages.hpp"
#include "features/passages/passage_report.hpp"
#include "features/passages/radial_passages.hpp"
#include "src/blade/blade_surface.hpp"
#include "src/brep/named_shape.hpp"

namespace cg::features {

/// Thickness between two groups of faces of `shape` (by face name predicates), min by BRepExtrema.
ThicknessMeasure measure_between(const brep::NamedShape& shape, const std::string& feature,
                                 const std::vector<std::string>& side_a, const std::vector<std::string>& side_b,
                                 double configured);

/// Every check and measure of the passages on the cooled blade.
void measure_passages(const blade::BladeModel& model, const brep::NamedShape& cooled, const PassagesDefinition& def,
                      const CoreBuild* core, const RadialPassageBuild* radial, PassageReport& report);

/// Cross-sections of the named passages ("chamber_2", "radial_passage_7") at the given spans: the
/// passages of span_sections (span_sections.hpp) on `cooled`, the sections sections.svg draws.
std::vector<PassageMeasure> passage_sections(const blade::BladeModel& model, const brep::NamedShape& cooled,
                                             const std::vector<double>& spans,
                                             const std::vector<std::string>& passages);

}  // namespace cg::features
