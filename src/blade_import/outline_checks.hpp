#pragma once
// Checks of input points that make one error each, naming a file line (internal to the import): the
// points of a run (a side LE -> TE, or a whole closed outline) and the crossing of an outline.
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

namespace cg::blade_import {

struct OutlineFault {
  int line = 0;      // file line to name
  std::string what;  // "duplicated point: ...", "points out of order: ...", "the outline crosses itself: ..."
};

/// Consecutive points closer than 1e-6 mm, or a turn back by more than 135 deg. `subject` names the run
/// ("the suction side", "the outline"), `order` says how the points must run ("LE -> TE"). `closed`: the
/// last point is followed by the first.
std::optional<OutlineFault> run_fault(const std::vector<Eigen::Vector3d>& p, const std::vector<int>& lines, bool closed,
                                      const std::string& subject, const std::string& order);
/// The closed outline projected on its best-fit plane crosses itself.
std::optional<OutlineFault> crossing_fault(const std::vector<Eigen::Vector3d>& loop, const std::vector<int>& lines);

}  // namespace cg::blade_import
