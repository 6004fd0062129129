#include "src/grid/section_grid.hpp"

#include <algorithm>
#include <cmath>

#include "src/core/format.hpp"
#include "src/core/error.hpp"
#include "src/grid/builders.hpp"
#include "src/grid/distribution.hpp"

namespace cg::grid {

namespace {


[[noreturn]] void bad(const std::string& option, const std::string& what) { throw InvalidGeometry(option + ": " + what); }

// Defaults relative to the chord, and the range checks that need the section.
SectionGridOptions resolve(const blade::SectionProfile& section, SectionGridOptions o) {
  const double chord = section.chord();
  if (o.cells_around < 8 || o.cells_around > 20000) bad("cells_around", "must be in [8, 20000], got " + std::to_string(o.cells_around));
  if (o.cells_normal < 2 || o.cells_normal > 5000) bad("cells_normal", "must be in [2, 5000], got " + std::to_string(o.cells_normal));
  if (!(o.growth_ratio > 1 && o.growth_ratio <= 2)) bad("growth_ratio", "must be in (1, 2], got " + format_value_range(o.growth_ratio, 1, 2).value);
  if (!(o.wall_clustering >= 0 && o.wall_clustering <= 10)) bad("wall_clustering", "must be in [0, 10], got " + format_value_range(o.wall_clustering, 0, 10).value);
  if (o.first_cell_height == 0) o.first_cell_height = 2e-4 * chord;
  if (o.thickness == 0) o.thickness = (o.cascade ? 0.03 : 0.1) * chord;
  if (!(o.first_cell_height > 0)) bad("first_cell_height", "must be > 0 mm, got " + format_number(o.first_cell_height));
  if (!(o.thickness > 0)) bad("thickness", "must be > 0 mm, got " + format_number(o.thickness));
  if (o.first_cell_height >= o.thickness) {
    const ValueLimitText t = format_value_limit(o.first_cell_height, o.thickness, Allowed::below);
    bad("first_cell_height", "must be below the thickness (" + t.limit + " mm), got " + t.value);
  }
  if (o.cascade) {
    CascadeOptions& c = *o.cascade;
    if (!(c.pitch > 0)) bad("cascade.pitch", "must be > 0 mm, got " + format_number(c.pitch));
    const int around = o.cells_around - c.inlet_cells_pitchwise - c.outlet_cells_pitchwise;
    if (c.inlet_cells_pitchwise < 2 || c.outlet_cells_pitchwise < 2 || around < 4 || around % 2 != 0)
      bad("cells_around", "in a cascade, cells_around - inlet pitchwise cells - outlet pitchwise cells must be even and >= 4 "
          "(the two periodic lines get half each), got " + std::to_string(o.cells_around) + " - " +
          std::to_string(c.inlet_cells_pitchwise) + " - " + std::to_string(c.outlet_cells_pitchwise));
    if (c.inlet_cells_streamwise < 1) bad("cascade.inlet_cells", "streamwise cells must be >= 1");
    if (c.outlet_cells_streamwise < 1) bad("cascade.outlet_cells", "streamwise cells must be >= 1");
    const auto [a_min, a_max] = detail::axial_range(section);
    const double c_ax = a_max - a_min;
    if (c.inlet_distance == 0) c.inlet_distance = 0.6 * c_ax;
    if (c.outlet_distance == 0) c.outlet_distance = 1.2 * c_ax;
    if (!(c.inlet_distance > 0)) bad("cascade.inlet_distance", "must be > 0 mm, got " + format_number(c.inlet_distance));
    if (!(c.outlet_distance > 0)) bad("cascade.outlet_distance", "must be > 0 mm, got " + format_number(c.outlet_distance));
    if (!(o.thickness < 0.2 * c.pitch)) {
      const ValueLimitText t = format_value_limit(o.thickness, 0.2 * c.pitch, Allowed::below);
      bad("thickness", "in a cascade the wall layers must stay below 0.2 pitch (" + t.limit + " mm), got " + t.value);
    }
  }
  return o;
}

// Smallest radius of curvature on the concave side (where the outer normals converge): normal lines
// longer than that cross.
double min_concave_radius(const blade::SectionProfile& section, const WallPatches& patches) {
  double r = HUGE_VAL;
  const auto& c = section.curve;
  for (int k = 0; k < 4000; ++k) {
    const double u = c.first_param() + c.period() * k / 4000;
    Eigen::Vector2d d[3];
    c.derivatives(u, 2, d);
    const double kappa = (d[1].x() * d[2].y() - d[1].y() * d[2].x()) / std::pow(d[1].norm(), 3);
    // Outer side left (side +1): the outer normals converge where the curve turns left (kappa > 0).
    if (patches.outer_side() * kappa > 0) r = std::min(r, 1 / std::abs(kappa));
  }
  return r;
}

}  // namespace

SectionGrid build_section_grid(const blade::SectionProfile& section, const SectionGridOptions& options) {
  const SectionGridOptions o = resolve(section, options);
  const WallPatches patches(section.curve, o.thickness);
  const double rmin = min_concave_radius(section, patches);
  if (!(o.thickness < 0.9 * rmin))
    bad("thickness", format_number(o.thickness) + " mm reaches past the centre of curvature of a concave part of the section "
        "(radius " + format_number(rmin) + " mm): the normal lines would cross; use less than " + format_limit(0.9 * rmin, Allowed::below) + " mm");
  detail::BuiltGrid built;
  if (o.cascade) {
    double reach = 0;
    int layers = 1;
    while ((reach = geometric_length(o.first_cell_height, o.growth_ratio, layers)) < o.thickness) ++layers;
    if (layers > o.cells_normal - 4)
      bad("thickness", "the wall layers need " + std::to_string(layers) + " cells (first cell " + format_number(o.first_cell_height) +
          " mm, growth " + format_number(o.growth_ratio) + ") but cells_normal = " + std::to_string(o.cells_normal) +
          " leaves fewer than 4 for the passage; raise cells_normal or lower the thickness");
    built = detail::build_cascade_grid(section, patches, o, layers);
  } else {
    geometric_then_uniform(o.first_cell_height, o.growth_ratio, o.cells_normal, o.thickness);  // throws if unreachable
    built = detail::build_o_grid(section, patches, o);
  }
  SectionGrid out;
  out.grid = std::move(built.grid);
  SectionGridReport& r = out.report;
  for (const Block& b : out.grid.blocks) {
    r.blocks.push_back(block_quality(b));
    r.cells += r.blocks.back().cells;
    r.inverted_cells += r.blocks.back().inverted_cells;
    r.min_scaled_jacobian = std::min(r.min_scaled_jacobian, r.blocks.back().min_scaled_jacobian);
  }
  for (const Connection& c : out.grid.connections)
    r.max_connection_mismatch = std::max(r.max_connection_mismatch, connection_mismatch(out.grid, c));
  r.wall = wall_quality(out.grid.blocks[static_cast<std::size_t>(built.wall_block)], section.curve, built.wall_params);
  r.patch_wall_angle_deviation_deg = patches.max_wall_angle_deviation_deg();
  r.wall_patches = patches.size();
  r.wall_patch_degree = patches.max_degree();
  r.thickness_fit_error = patches.thickness_fit_error();
  r.wall_layers = built.wall_layers;
  r.first_cell_height = o.first_cell_height;
  r.growth_ratio = o.growth_ratio;
  r.thickness = o.thickness;
  if (r.inverted_cells > 0 && !o.cascade)  // every node is on an exact normal line: they cross
    bad("thickness", format_number(o.thickness) + " mm is too large for this section: its normal lines cross (" +
        std::to_string(r.inverted_cells) + " inverted cells), the offset folds across a concave stretch; reduce it");
  if (r.inverted_cells > 0) {
    std::string which;
    for (const BlockQuality& q : r.blocks)
      if (q.inverted_cells > 0) which += " " + q.name + " (" + std::to_string(q.inverted_cells) + " cells)";
    throw AlgorithmFailure("grid: inverted cells in" + which + "; try a smaller thickness, more cells_around or a larger pitch");
  }
  if (r.max_connection_mismatch > 1e-9 * (1 + section.chord()))
    throw AlgorithmFailure("grid: block interfaces do not match (" + format_number(r.max_connection_mismatch) + " mm)");
  return out;
}

}  // namespace cg::grid
