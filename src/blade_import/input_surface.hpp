#pragma once
// The blade surface an imported file defines (internal to the import): every input section is the
// closed periodic cubic through its points (suction side LE -> TE, then the pressure side back to the
// LE; centripetal parameters, as point sections are), sampled at the same per-side arc-length
// fractions (clustered at the LE and TE); between sections each such sample follows the natural cubic
// spline over the sections' mean spanwise position (the radius of an annular row, z of a cascade),
// in (x, r, theta) for annular rows and (x, y, z) for cascades.
//
// The constructor checks each section first, so hostile input gets one error naming the file, the
// section and a line: fewer than 3 points on a side, duplicated (coincident consecutive) points,
// sides that do not meet at the LE or the TE (an open section), points out of order (a side turning
// back), a section outline that crosses itself, sections not ordered from hub to tip.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "src/blade/span_spline.hpp"
#include "src/blade_import/imported_blade.hpp"
#include "src/core/bspline_curve.hpp"

namespace cg::blade_import {

class InputSurface {
 public:
  /// samples_per_side >= 8; gap_tolerance: the largest distance (mm) between the suction and
  /// pressure sides' end points still taken as one LE / TE point. Throws InvalidGeometry
  /// "<file>:<line>: section k: ...".
  InputSurface(const ImportedBlade& blade, int samples_per_side, double gap_tolerance);

  std::size_t sections() const { return curves_.size(); }
  /// Chordwise samples around the outline: j in [0, M] the suction side LE -> TE, then the pressure
  /// side from the TE back towards the LE (2M in all; j = 0 is the LE, j = M the TE).
  int loop_size() const { return 2 * m_; }
  int samples_per_side() const { return m_; }
  /// Spanwise parameter of section k (its mean radius, or mean z of a cascade), strictly increasing.
  double section_tau(std::size_t k) const { return taus_[k]; }
  /// Chordwise sample j at spanwise parameter tau (3D, mm).
  Eigen::Vector3d point(int j, double tau) const;
  /// Section k's closed curve and the parameters of its input points along the loop (LE = 0).
  const BSplineCurve<3>& section_curve(std::size_t k) const { return curves_[k]; }
  const std::vector<double>& point_params(std::size_t k) const { return params_[k]; }
  /// Input points of section k along the loop and their file lines.
  const std::vector<Eigen::Vector3d>& loop_points(std::size_t k) const { return loops_[k]; }
  const std::vector<int>& loop_lines(std::size_t k) const { return lines_[k]; }

 private:
  Eigen::Vector3d to_cartesian(const Eigen::Vector3d& q) const;
  RowKind kind_;
  int m_ = 0;
  std::vector<BSplineCurve<3>> curves_;
  std::vector<std::vector<double>> params_;
  std::vector<std::vector<Eigen::Vector3d>> loops_;
  std::vector<std::vector<int>> lines_;
  std::vector<double> taus_;
  blade::detail::SpanSpline spline_;
  std::vector<std::vector<Eigen::Vector3d>> samples_;  // [j][k]: sample j of section k, (x, r, theta) or (x, y, z)
};

/// "section 3 (line 120)" for messages.
std::string section_name(const ImportedBlade& blade, std::size_t k);

}  // namespace cg::blade_import
