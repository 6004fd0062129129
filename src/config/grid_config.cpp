#include "src/config/grid_config.hpp"

#include <algorithm>

namespace cg::config {

GridConfig parse_grid_config(const Field& f, std::size_t section_count) {
  f.expect_object({"sections", "cells_around", "cells_normal", "first_cell_height", "growth_ratio", "thickness",
                   "wall_clustering", "cascade"});
  GridConfig g;
  g.given = true;
  if (f.has("sections")) {
    const Field s = f.at("sections");
    const std::size_t n = s.expect_array(1, section_count);
    for (std::size_t i = 0; i < n; ++i) {
      const int k = s.item(i).integer(0, static_cast<int>(section_count) - 1);
      if (std::find(g.sections.begin(), g.sections.end(), k) != g.sections.end())
        fail(s.item(i).path(), "section " + std::to_string(k) + " is listed twice");
      g.sections.push_back(k);
    }
  }
  grid::SectionGridOptions& o = g.options;
  o.cells_around = f.integer_or("cells_around", o.cells_around, 8, 20000);
  o.cells_normal = f.integer_or("cells_normal", o.cells_normal, 2, 5000);
  // 0 keeps the chord-relative default (see section_grid.hpp); given values must be positive.
  if (f.has("first_cell_height")) o.first_cell_height = f.at("first_cell_height").number(positive(1000), "mm");
  o.growth_ratio = f.number_or("growth_ratio", o.growth_ratio, {1.0, 2.0, true, false});
  if (f.has("thickness")) o.thickness = f.at("thickness").number(positive(10000), "mm");
  o.wall_clustering = f.number_or("wall_clustering", o.wall_clustering, closed(0, 10));
  if (f.has("cascade")) {
    const Field c = f.at("cascade");
    c.expect_object({"pitch", "inlet_cells", "outlet_cells", "inlet_distance", "outlet_distance"});
    grid::CascadeOptions cas;
    cas.pitch = c.at("pitch").number(positive(100000), "mm");
    auto cells = [&](const char* key, int& streamwise, int& pitchwise) {
      if (!c.has(key)) return;
      const Field a = c.at(key);
      a.expect_array(2, 2);
      streamwise = a.item(0).integer(1, 5000);
      pitchwise = a.item(1).integer(2, 5000);
    };
    cells("inlet_cells", cas.inlet_cells_streamwise, cas.inlet_cells_pitchwise);
    cells("outlet_cells", cas.outlet_cells_streamwise, cas.outlet_cells_pitchwise);
    if (c.has("inlet_distance")) cas.inlet_distance = c.at("inlet_distance").number(positive(1e5), "mm");
    if (c.has("outlet_distance")) cas.outlet_distance = c.at("outlet_distance").number(positive(1e5), "mm");
    const int periodic = o.cells_around - cas.inlet_cells_pitchwise - cas.outlet_cells_pitchwise;
    if (periodic < 4 || periodic % 2 != 0)
      fail(f.path() + ".cells_around", "with a cascade, cells_around - inlet pitchwise cells - outlet pitchwise cells "
           "must be even and >= 4 (each periodic line gets half), got " + std::to_string(o.cells_around) + " - " +
           std::to_string(cas.inlet_cells_pitchwise) + " - " + std::to_string(cas.outlet_cells_pitchwise));
    o.cascade = cas;
  }
  return g;
}

std::vector<int> grid_sections(const GridConfig& g, std::size_t section_count) {
  if (!g.sections.empty()) return g.sections;
  std::vector<int> all(section_count);
  for (std::size_t k = 0; k < section_count; ++k) all[k] = static_cast<int>(k);
  return all;
}

}  // namespace cg::config
