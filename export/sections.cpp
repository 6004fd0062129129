#include "export/sections.hpp"

namespace cg::io {

nlohmann::ordered_json sections_json(const std::vector<features::SpanSection>& cuts) {
  using json = nlohmann::ordered_json;
  json out = json::array();
  for (const auto& c : cuts) {
    json passages = json::array(), holes = json::array();
    for (const auto& p : c.passages)
      passages.push_back({{"name", p.name},
                          {"area_mm2", p.area},
                          {"wetted_perimeter_mm", p.wetted_perimeter},
                          {"hydraulic_diameter_mm", p.hydraulic_diameter},
                          {"loops", p.loops}});
    double hole_area = 0;
    for (const auto& h : c.holes) {
      holes.push_back({{"name", h.name}, {"area_mm2", h.area}});
      hole_area += h.area;
    }
    json s = {{"span", c.span},         {"chord_mm", c.chord},   {"metal_area_mm2", c.metal_area},
              {"passages", passages},   {"hole_count", c.holes.size()}, {"hole_area_mm2", hole_area},
              {"holes", holes}};
    if (c.unclosed_openings > 0) s["unclosed_openings"] = c.unclosed_openings;
    out.push_back(std::move(s));
  }
  return out;
}

}  // namespace cg::io
