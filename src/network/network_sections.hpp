#pragma once
// The stations of the coolant passages measured on the part as built (docs/network.md): one call of the
// project's section routine (features/passages/span_sections.hpp) on every body of the built part, so a
// station's area is the cavity's coolant area in that cut (walls closed over the holes that cross it,
// the metal of an insert inside excluded).
#include <map>
#include <string>
#include <vector>

#include "features/passages/passage_report.hpp"
#include "src/blade/blade_surface.hpp"
#include "src/brep/named_shape.hpp"

namespace cg::network {

/// Passage name -> its sections at `spans` (ascending span). A passage is missing at a span where its
/// cavity is joined to another one (a turnaround's gap) or where it is not cut.
std::map<std::string, std::vector<features::CrossSection>> measure_stations(const blade::BladeModel& model,
                                                                           const brep::Part& part,
                                                                           std::vector<double> spans);

}  // namespace cg::network
