#pragma once
// The "grid" section of the configuration: structured grids around the blade sections
// (src/grid/section_grid.hpp), documented field by field in data/schema/coolinggen.schema.json.
//   "grid": {"sections": [0, 2], "cells_around": 175, "cells_normal": 59, "first_cell_height": 0.02,
//            "growth_ratio": 1.15, "thickness": 3.0, "wall_clustering": 0.5,
//            "cascade": {"pitch": 117.73, "inlet_cells": [19, 30], "outlet_cells": [39, 49],
//                        "inlet_distance": 50, "outlet_distance": 90}}
// Every field is optional; without the section (or without a field) the defaults of
// grid::SectionGridOptions apply and every defined section is gridded.
#include <vector>

#include "src/config/json_fields.hpp"
#include "src/grid/section_grid.hpp"

namespace cg::config {

struct GridConfig {
  bool given = false;         ///< the document has a "grid" section
  std::vector<int> sections;  ///< indices into "sections"; empty = all
  grid::SectionGridOptions options;
};

/// Parses the "grid" object (field `f`, path "grid"); `section_count` bounds the section indices.
GridConfig parse_grid_config(const Field& f, std::size_t section_count);

/// Indices of the sections to grid (all when none are listed).
std::vector<int> grid_sections(const GridConfig& g, std::size_t section_count);

}  // namespace cg::config
