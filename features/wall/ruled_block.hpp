#pragma once
// A feature tool bounded by two B-spline surfaces with one parametrisation: the solid
//   Y(a, b, l) = B(a, b) + l (T(a, b) - B(a, b)),  (a, b) in the surfaces' domain, l in [0, 1],
// bounded by B, T and the four ruled surfaces between their boundary iso-curves (exact B-splines:
// a ruled surface between two compatible curves is degree 1 across). Used for turbulators (B inside the
// wall, T the turbulator's top) and trailing-edge slots (planar B and T).
//
// Its volume inside a region of the hollow blade (material, chamber) is integrated without OCCT:
// det(Y_a, Y_b, Y_l) is a quadratic polynomial in l (Y_l = T - B does not depend on l), so on each
// interval of the line a -> b in the region (WallLines::intervals, exact surface crossings) 2-point
// Gauss-Legendre is exact; over (a, b), 8-point Gauss-Legendre on each knot span (the integrand is
// smooth inside one).
#include <string>
#include <vector>

#include "features/wall/wall_lines.hpp"
#include "src/brep/named_shape.hpp"
#include "src/core/bspline_surface.hpp"

namespace cg::features {

struct RuledBlock {
  BSplineSurface<3> bottom, top;  ///< same degrees and knot vectors
};

/// The B-rep solid of the block, every face named `name`. Throws FeatureFailure when sewing does not
/// give one closed solid.
brep::NamedShape ruled_block_solid(const RuledBlock& block, const std::string& name);

/// Volume of the block, and of its part in `wanted` when the bottom lies in `start` (every line from
/// B to T must end in `end`, else `ok` is false: the block is not placed as assumed).
struct BlockIntegral {
  double volume = 0;     ///< of the whole block
  double in_region = 0;  ///< of its part in the wanted region
  bool ok = true;
};
/// Gauss-Legendre cells per knot span (between breaks) along a and b; `breaks_a`: extra a-parameters where
/// the integrand has a kink (a line through a crease or grazing an edge of the wall), so no Gauss cell
/// straddles one; `chamber`: false when the block cannot reach the chamber (the inner wall is skipped).
struct BlockQuadrature {
  int cells_a = 1, cells_b = 1;
  std::vector<double> breaks_a;
  bool chamber = true;
};
BlockIntegral integrate_block(const RuledBlock& block, WallLines& lines, Region start, Region wanted, Region end,
                              const BlockQuadrature& q = {});

/// A planar quadrilateral (corners p00, p10, p01, p11 in the (a, b) order) as a bilinear B-spline patch.
BSplineSurface<3> bilinear_patch(const Eigen::Vector3d& p00, const Eigen::Vector3d& p10, const Eigen::Vector3d& p01,
                                 const Eigen::Vector3d& p11);

}  // namespace cg::features
