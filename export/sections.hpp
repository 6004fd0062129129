#pragma once
// The section table of report.json / report.md ("sections") from the span sections of the part
// (features/passages/span_sections.hpp: the sections sections.svg draws and the design checks measure).
#include <nlohmann/json.hpp>

#include <vector>

#include "features/passages/span_sections.hpp"

namespace cg::io {

/// [{"span", "chord_mm", "metal_area_mm2", "passages": [{"name", "area_mm2", "wetted_perimeter_mm",
/// "hydraulic_diameter_mm", "loops"}], "hole_count", "hole_area_mm2", "holes": [{"name", "area_mm2"}]}]
/// ("unclosed_openings" only when an opening's walls could not be closed).
nlohmann::ordered_json sections_json(const std::vector<features::SpanSection>& cuts);

}  // namespace cg::io
