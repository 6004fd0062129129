#pragma once
// Structured grids around a blade section (2D, in the section's own frame (a, b), mm) with grid lines
// that leave the wall at right angles, as in the CFD application of Lang & Schroecker 1999 (Fig. 6: a
// periodic O-grid of 175 x 59 cells around a turbine vane with inlet and outlet blocks).
//
// The wall layers are built on the exact orthogonal continuation of the section (wall_patches.hpp): every
// node of those layers lies on the straight normal line through its wall node, at a prescribed wall
// distance, so the grid lines meet the wall at 90 deg up to rounding and the first cell has exactly the
// configured height.
//
// Two layouts:
//  - O-grid (no cascade): one block "o_grid", cells_around x cells_normal, every layer on the wall patches
//    out to `thickness` (geometric growth from first_cell_height by growth_ratio, uniform once the
//    spacing reaches the uniform spacing of the rest). Boundaries: "wall" (j = 0), "outer" (farfield,
//    j = nj), the periodic cut i = 0 / i = ni ("o_cut").
//  - cascade (pitch given): the O-grid's outer boundary is the passage: the inlet interface (a line of
//    constant a upstream of the LE), the two periodic lines (the section's mid-line shifted by +-pitch/2
//    across the passage, node-matched), the outlet interface downstream of the TE (the near wake stays in
//    the O-grid). Outer nodes are uniform along each of the four pieces. The wall layers out to
//    `thickness` are on the wall patches (geometric growth); the rest of each grid line is a cubic Hermite
//    curve leaving the last wall layer along the wall normal, with cells growing geometrically to its
//    outer node. Wall node i belongs to outer node i through the normal rays: the ray from the last wall
//    layer first hits the outer loop at tau(s); the wall nodes are tau^-1 of the outer nodes (smoothed,
//    with a share of the uniform correspondence). A local untangling and a quality-guarded smoothing of
//    the passage part finish the O-grid. Blocks "inlet" and "outlet" (H-type, periodic in the pitchwise
//    direction) continue to the inlet and outlet planes. Paper layout and our defaults: O-grid 175 x 59 =
//    inlet-interface cells (30) + 2 x periodic cells (48) + outlet-interface cells (49) around; inlet
//    19 x 30, outlet 39 x 49.
// Every block is checked: no cell with a non-positive corner Jacobian, connections node-matched.
#include <optional>
#include <string>
#include <vector>

#include "src/blade/section.hpp"
#include "src/grid/block.hpp"
#include "src/grid/grid_quality.hpp"

namespace cg::grid {

struct CascadeOptions {
  double pitch = 0;                       ///< mm, > 0 (in the section frame, across the passage = +b)
  int inlet_cells_streamwise = 19, inlet_cells_pitchwise = 30;
  int outlet_cells_streamwise = 39, outlet_cells_pitchwise = 49;
  double inlet_distance = 0;              ///< mm from the section's most upstream point to the inlet; 0: 0.6 axial chords
  double outlet_distance = 0;             ///< mm from the most downstream point to the outlet; 0: 1.2 axial chords
};

struct SectionGridOptions {
  int cells_around = 175;          ///< O-grid cells around the section
  int cells_normal = 59;           ///< O-grid cells from the wall outwards
  double first_cell_height = 0;    ///< mm; 0: 2e-4 chord
  double growth_ratio = 1.15;      ///< largest ratio of neighbouring cells in the wall layers, (1, 2]
  /// mm; 0: 0.1 chord (O-grid) / 0.03 chord (cascade). O-grid: outer thickness. Cascade: depth of the wall
  /// layers on the exact normal lines.
  double thickness = 0;
  /// O-grid only: wall nodes equidistribute 1 + clustering |curvature| perimeter / (2 pi) (smoothed), so
  /// the LE and TE get finer cells; 0 = uniform arc length. [0, 10].
  double wall_clustering = 0.5;
  std::optional<CascadeOptions> cascade;
};

struct SectionGridReport {
  std::vector<BlockQuality> blocks;
  WallQuality wall;                      ///< measured on the grid: first line off the wall vs the exact tangent
  double patch_wall_angle_deviation_deg = 0;  ///< measured on the wall patches' derivatives
  int wall_patches = 0, wall_patch_degree = 0;
  double thickness_fit_error = 0;        ///< of L, Q (before the common scaling), see wall_patches.hpp
  double max_connection_mismatch = 0;    ///< mm
  int wall_layers = 0;                   ///< layers on the exact normal lines
  double first_cell_height = 0, growth_ratio = 0, thickness = 0;  ///< the values used (defaults resolved)
  int cells = 0, inverted_cells = 0;
  double min_scaled_jacobian = 1;
};

struct SectionGrid {
  MultiBlockGrid grid;
  SectionGridReport report;
};

/// Builds and checks the grid. Throws InvalidGeometry naming the offending option (by its config name,
/// e.g. "thickness", "cascade.pitch") and the allowed range for impossible settings, AlgorithmFailure
/// when the result has inverted cells (with the block and the count).
SectionGrid build_section_grid(const blade::SectionProfile& section, const SectionGridOptions& options);

}  // namespace cg::grid
