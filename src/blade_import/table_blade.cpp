#include "src/blade_import/table_blade.hpp"

#include <Eigen/Dense>
#include <cmath>

#include "src/blade/section.hpp"
#include "src/blade_import/outline_checks.hpp"
#include "src/core/constants.hpp"
#include "src/core/error.hpp"
#include "src/core/format.hpp"

namespace cg::blade_import {
namespace {

[[noreturn]] void fail(const SectionTable& t, std::size_t k, int line, const std::string& what) {
  throw InvalidGeometry(t.file + ":" + std::to_string(line) + ": section " + std::to_string(k + 1) + ": " + what);
}

// The outline unrolled onto its stream surface: cascades (x, y); annular rows (m, r_mean theta) with m
// along the outline's main direction in the (x, r) plane and theta unwrapped from the first point.
std::vector<Eigen::Vector2d> unrolled(const std::vector<Eigen::Vector3d>& p, RowKind kind) {
  std::vector<Eigen::Vector2d> q;
  if (kind == RowKind::Cascade) {
    for (const auto& v : p) q.emplace_back(v.x(), v.y());
    return q;
  }
  std::vector<Eigen::Vector2d> xr;
  std::vector<double> th;
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const auto& v : p) {
    xr.emplace_back(v.x(), std::hypot(v.y(), v.z()));
    const double t = std::atan2(v.z(), v.y());
    th.push_back(th.empty() ? t : th.back() + std::remainder(t - th.back(), 2 * kPi));
    mean += xr.back();
  }
  mean /= static_cast<double>(p.size());
  Eigen::Matrix2d cov = Eigen::Matrix2d::Zero();
  for (const auto& v : xr) cov += (v - mean) * (v - mean).transpose();
  const Eigen::Vector2d d = Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d>(cov).eigenvectors().col(1);
  for (std::size_t i = 0; i < p.size(); ++i) q.emplace_back((xr[i] - mean).dot(d), mean.y() * th[i]);
  return q;
}

std::size_t nearest(const std::vector<Eigen::Vector2d>& q, const Eigen::Vector2d& p) {
  std::size_t best = 0;
  for (std::size_t i = 1; i < q.size(); ++i)
    if ((q[i] - p).squaredNorm() < (q[best] - p).squaredNorm()) best = i;
  return best;
}

void check_closed(const SectionTable& t, std::size_t k) {
  const std::size_t n = t.points.size();
  double longest = 0;
  for (std::size_t i = 0; i + 1 < n; ++i) longest = std::max(longest, (t.points[i + 1] - t.points[i]).norm());
  const double gap = (t.points.front() - t.points.back()).norm();
  if (gap > 3 * longest)
    fail(t, k, t.lines.back(), "open section: the last point (line " + std::to_string(t.lines.back()) + ") is " +
                                   format_number(gap) + " mm from the first (line " + std::to_string(t.lines.front()) +
                                   "), more than 3 times the longest step between the other consecutive points; a table "
                                   "lists the whole outline (both sides) once around");
}

ImportedSection section_of(const SectionTable& t, std::size_t k, RowKind kind, blade::EdgeRule edges) {
  if (const auto f = run_fault(t.points, t.lines, true, "the outline", "once around the section")) fail(t, k, f->line, f->what);
  check_closed(t, k);
  if (const auto f = crossing_fault(t.points, t.lines)) fail(t, k, f->line, f->what);
  blade::PointSectionDefinition def;
  def.points = unrolled(t.points, kind);
  def.edges = edges;
  blade::SectionProfile profile;
  try {
    profile = blade::section_from_points(def);
  } catch (const Error& e) {
    fail(t, k, t.lines.front(), std::string("its LE and TE could not be found: ") + e.what());
  }
  const std::size_t n = t.points.size(), le = nearest(def.points, profile.le), te = nearest(def.points, profile.te);
  if (le == te) fail(t, k, t.lines[le], "its LE and TE fall on the same point; give more points around the edges");
  ImportedSection forward, backward;  // LE -> TE one way round and the other
  for (std::size_t i = le;; i = (i + 1) % n) {
    forward.suction.push_back(t.points[i]);
    forward.suction_lines.push_back(t.lines[i]);
    if (i == te) break;
  }
  for (std::size_t i = le;; i = (i + n - 1) % n) {
    backward.suction.push_back(t.points[i]);
    backward.suction_lines.push_back(t.lines[i]);
    if (i == te) break;
  }
  auto length = [](const std::vector<Eigen::Vector3d>& p) {
    double s = 0;
    for (std::size_t i = 0; i + 1 < p.size(); ++i) s += (p[i + 1] - p[i]).norm();
    return s;
  };
  if (length(forward.suction) < length(backward.suction)) std::swap(forward, backward);
  ImportedSection s;
  s.suction = std::move(forward.suction);
  s.suction_lines = std::move(forward.suction_lines);
  s.pressure = std::move(backward.suction);
  s.pressure_lines = std::move(backward.suction_lines);
  s.line = t.lines.front();
  s.file = t.file;
  return s;
}

}  // namespace

ImportedBlade blade_from_tables(const std::vector<SectionTable>& tables, RowKind kind, const std::vector<Eigen::Vector2d>& hub,
                                const std::vector<Eigen::Vector2d>& casing, blade::EdgeRule edges) {
  ImportedBlade b;
  b.kind = kind;
  for (std::size_t k = 0; k < tables.size(); ++k) {
    b.file += (k ? ", " : "") + tables[k].file;
    b.sections.push_back(section_of(tables[k], k, kind, edges));
  }
  b.hub = hub;
  b.casing = casing;
  return b;
}

}  // namespace cg::blade_import
