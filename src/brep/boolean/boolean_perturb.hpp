#pragma once
// Small perturbations of a tool for a retry, after the booleans notes: rotating a tool about its own
// axis (which moves its seam) or shifting it by ~0.01 mm cured every wrong single-tool cut measured.
#include <gp_Ax1.hxx>

#include <optional>
#include <string>

#include "src/brep/named_shape.hpp"

namespace cg::features {

/// The common axis of a tool bounded only by coaxial cylinders/cones and planes across that axis
/// (so a rotation about it leaves the solid unchanged); nullopt otherwise.
std::optional<gp_Ax1> detect_symmetry_axis(const TopoDS_Shape& tool);

struct Perturbed {
  brep::NamedShape shape;
  bool same_geometry = false;  ///< a rotation about a symmetry axis: the expected volume still holds
  std::string what;            ///< e.g. "rotated 21.2 deg about its axis", "shifted 0.010 mm"
};

/// Retry number `attempt` (1, 2, ...): odd attempts rotate about `axis` when there is one (by 0.37 rad,
/// then 1.2 rad more, away from the seam and from quarter turns), the others shift by
/// attempt/2 * `shift` mm across the axis, diagonally (or along (1, 1, 1) without an axis). Names
/// follow the faces (the faces are moved, not rebuilt).
Perturbed perturb_tool(const brep::NamedShape& tool, const std::optional<gp_Ax1>& axis, int attempt, double shift);

}  // namespace cg::features
