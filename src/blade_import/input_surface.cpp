#include "src/blade_import/input_surface.hpp"

#include <cmath>

#include "src/analyze/arc_length.hpp"
#include "src/blade_import/outline_checks.hpp"
#include "src/core/constants.hpp"
#include "src/core/error.hpp"
#include "src/core/format.hpp"
#include "src/fit/interpolate.hpp"

namespace cg::blade_import {
namespace {

[[noreturn]] void fail(const ImportedBlade& b, std::size_t k, int line, const std::string& what) {
  throw InvalidGeometry(b.file_of(k) + ":" + std::to_string(line) + ": section " + std::to_string(k + 1) + ": " + what);
}

// Sides: enough points, none repeated, none turning back.
void check_side(const ImportedBlade& b, std::size_t k, const std::vector<Eigen::Vector3d>& p,
                const std::vector<int>& lines, const char* side) {
  if (p.size() < 3)
    fail(b, k, b.sections[k].line, std::string("the ") + side + " side has " + std::to_string(p.size()) + " points, needs >= 3");
  if (const auto f = run_fault(p, lines, false, std::string("the ") + side + " side", "LE -> TE")) fail(b, k, f->line, f->what);
}

// Side fractions clustered at both ends: (1 - cos(pi i / m)) / 2.
std::vector<double> side_fractions(int m) {
  std::vector<double> f;
  for (int i = 0; i <= m; ++i) f.push_back(0.5 * (1 - std::cos(kPi * i / m)));
  return f;
}

}  // namespace

std::string section_name(const ImportedBlade& blade, std::size_t k) {
  return "section " + std::to_string(k + 1) + " (line " + std::to_string(blade.sections[k].line) + ")";
}

InputSurface::InputSurface(const ImportedBlade& b, int samples_per_side, double gap_tolerance)
    : kind_(b.kind), m_(samples_per_side) {
  require(b.sections.size() >= 2, b.file_of(0) + ": " + std::to_string(b.sections.size()) +
                                      " section given; at least 2 (reaching past hub and casing) are needed");
  const std::vector<double> f = side_fractions(m_);
  samples_.assign(static_cast<std::size_t>(2 * m_), {});
  for (std::size_t k = 0; k < b.sections.size(); ++k) {
    const ImportedSection& s = b.sections[k];
    check_side(b, k, s.suction, s.suction_lines, "suction");
    check_side(b, k, s.pressure, s.pressure_lines, "pressure");
    const double gap_le = (s.suction.front() - s.pressure.front()).norm();
    const double gap_te = (s.suction.back() - s.pressure.back()).norm();
    if (gap_le > gap_tolerance || gap_te > gap_tolerance) {
      const bool le = gap_le > gap_tolerance;
      fail(b, k, le ? s.pressure_lines.front() : s.pressure_lines.back(),
           std::string("open section: the suction and pressure sides do not meet at the ") + (le ? "LE" : "TE") +
               " (lines " + std::to_string(le ? s.suction_lines.front() : s.suction_lines.back()) + " and " +
               std::to_string(le ? s.pressure_lines.front() : s.pressure_lines.back()) + " are " +
               format_number(le ? gap_le : gap_te) + " mm apart, more than blade.import.tolerance " +
               format_number(gap_tolerance) + " mm); both sides run LE -> TE and share their end points");
    }
    std::vector<Eigen::Vector3d> loop = s.suction;
    std::vector<int> lines = s.suction_lines;
    for (std::size_t i = s.pressure.size() - 2; i >= 1; --i) {
      loop.push_back(s.pressure[i]);
      lines.push_back(s.pressure_lines[i]);
    }
    if (const auto f = crossing_fault(loop, lines)) fail(b, k, f->line, f->what);
    std::vector<double> params = interpolation_parameters<3>(loop, ParamMethod::Centripetal, true);
    BSplineCurve<3> curve = interpolate_closed<3>(loop, 3, params, periodic_interpolation_knots(params, 3));
    const double t_te = params[s.suction.size() - 1];
    const ArcLength<3> suction(curve, 0.0, t_te), pressure(curve, t_te, 1.0);
    double mean = 0;
    for (const auto& p : loop) mean += kind_ == RowKind::Cascade ? p.z() : std::hypot(p.y(), p.z());
    taus_.push_back(mean / static_cast<double>(loop.size()));
    if (k > 0 && taus_[k] <= taus_[k - 1])
      fail(b, k, s.line, "sections are not ordered from hub to tip: this one lies below section " + std::to_string(k));
    for (int j = 0; j < 2 * m_; ++j) {
      const double u = j <= m_ ? suction.param_at(f[static_cast<std::size_t>(j)] * suction.total())
                               : pressure.param_at(f[static_cast<std::size_t>(j - m_)] * pressure.total());
      const Eigen::Vector3d p = curve.point(u);
      Eigen::Vector3d q = p;
      if (kind_ == RowKind::Annular) {
        double th = std::atan2(p.z(), p.y());
        if (k > 0) th = samples_[static_cast<std::size_t>(j)][k - 1].z() + std::remainder(th - samples_[static_cast<std::size_t>(j)][k - 1].z(), 2 * kPi);
        q = Eigen::Vector3d(p.x(), std::hypot(p.y(), p.z()), th);
      }
      samples_[static_cast<std::size_t>(j)].push_back(q);
    }
    curves_.push_back(std::move(curve));
    params_.push_back(std::move(params));
    loops_.push_back(std::move(loop));
    lines_.push_back(std::move(lines));
  }
  spline_ = blade::detail::SpanSpline(taus_);
}

Eigen::Vector3d InputSurface::to_cartesian(const Eigen::Vector3d& q) const {
  if (kind_ == RowKind::Cascade) return q;
  return Eigen::Vector3d(q.x(), q.y() * std::cos(q.z()), q.y() * std::sin(q.z()));
}

Eigen::Vector3d InputSurface::point(int j, double tau) const {
  const std::vector<double> w = spline_.weights(tau);
  const auto& s = samples_[static_cast<std::size_t>(j)];
  Eigen::Vector3d q = Eigen::Vector3d::Zero();
  for (std::size_t k = 0; k < s.size(); ++k) q += w[k] * s[k];
  return to_cartesian(q);
}

}  // namespace cg::blade_import
