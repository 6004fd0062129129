#pragma once
// A blade given as CAD (blade.import format "step" or "iges") turned into the import's input sections:
// the file's faces (a solid's, a shell's or loose surfaces; faces lying on the hub or casing are left
// out) cut at `cuts` stream surfaces of the config's flow path (annular rows: surfaces of revolution of
// its streamlines; cascades: planes z = const), about evenly spaced in span from just inside the hub to
// just inside the casing (a quarter of the tolerance: a blade ending exactly on hub and casing, as solids do,
// is cut where it has a wall; slice_blade extrapolates the rest). Each cut must be one closed outline;
// it becomes a section table handed to blade_from_tables, so LE/TE detection, slicing, the blade model
// and the fidelity are those of every import. The faces are also sampled on a grid of their surface
// parameters (face_samples.hpp): those points inside the flow path are the blade's surface_samples, at
// which the fidelity is measured between the cuts.
#include <string>
#include <vector>

#include "src/blade/camber_edges.hpp"
#include "src/blade/meridional_net.hpp"
#include "src/blade_import/imported_blade.hpp"
#include "src/cad_import/cad_shape_reader.hpp"

namespace cg::cad_import {

struct CadCutOptions {
  int cuts = 15;              // >= 2
  double tolerance = 0.01;    // mm: blade.import.tolerance (gaps between faces, end faces, reach)
  double chord_error = 0.001; // mm: sampling of the cut outlines
  int face_samples = 4000;    // grid points over all faces (about)
  blade::EdgeRule edges = blade::EdgeRule::CentreLine;  // LE / TE of each cut (blade.import.edges)
};

/// `kind`, `hub`, `casing` as blade_from_tables takes them; `channel`: the meridional flow path's
/// definition (annular rows), null for a cascade. Throws InvalidGeometry "<file>: ..." naming the cut
/// (its span) that is empty, open or not one outline; AlgorithmFailure when OCCT fails.
blade_import::ImportedBlade read_cad_blade(const std::string& path, CadFormat format, blade_import::RowKind kind,
                                           const std::vector<Eigen::Vector2d>& hub, const std::vector<Eigen::Vector2d>& casing,
                                           const blade::MeridionalNetDefinition* channel, const CadCutOptions& options);

}  // namespace cg::cad_import
