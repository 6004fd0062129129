#include "src/config/point_checks.hpp"

#include "src/blade/planar_polyline.hpp"
#include "src/config/json_fields.hpp"

namespace cg::config {
namespace {

// The points as section_from_points uses them (a last point repeating the first dropped; a file's
// reader has dropped it already).
std::vector<Eigen::Vector2d> outline(const blade::PointSectionDefinition& def) {
  std::vector<Eigen::Vector2d> pts = def.points;
  if (pts.size() > 1 && (pts.front() - pts.back()).norm() <= 1e-12 * (1.0 + pts.front().norm())) pts.pop_back();
  return pts;
}

std::string label(const PointSource& s, std::size_t i) {
  if (i < s.lines.size()) return "line " + std::to_string(s.lines[i]);
  return "values[" + std::to_string(i) + "]";
}

std::string field_of(const PointSource& s) { return s.field + (s.file.empty() ? ".values" : ".file"); }

}  // namespace

void check_point_outline(const blade::PointSectionDefinition& def, const PointSource& source) {
  const std::vector<Eigen::Vector2d> pts = outline(def);
  const std::size_t n = pts.size();
  if (n < 4) return;  // the model's message (at least 4 points) needs no line numbers
  const std::string in_file = source.file.empty() ? "" : "'" + source.file + "' ";
  double size = 0;
  for (const auto& p : pts) size = std::max(size, (p - pts.front()).norm());
  for (std::size_t i = 0; i < n; ++i)
    if ((pts[(i + 1) % n] - pts[i]).norm() <= 1e-12 * size)
      fail(field_of(source), in_file + label(source, i) + " and " + label(source, (i + 1) % n) +
                                 " give the same point; remove one");
  int a = 0, b = 0;
  if (!blade::detail::polygon_is_simple(pts, a, b)) {
    const auto seg = [&](int k) {
      return label(source, static_cast<std::size_t>(k)) + " - " + label(source, static_cast<std::size_t>(k + 1) % n);
    };
    fail(field_of(source), in_file + "the outline crosses itself: segment " + seg(a) + " crosses segment " + seg(b) +
                               " (the points must go once around the profile, in order)");
  }
}

std::string le_te_index_hint(const blade::PointSectionDefinition& def, const PointSource& source) {
  const std::size_t n = outline(def).size();
  std::string hint = "give \"le_index\" and \"te_index\" in " + source.field +
                     " to set the leading- and trailing-edge points (indices count the points from 0 in the order given";
  if (!source.lines.empty() && n > 0)
    hint += ": index 0 is line " + std::to_string(source.lines.front()) + ", index " + std::to_string(n - 1) + " is line " +
            std::to_string(source.lines[n - 1]);
  return hint + ")";
}

}  // namespace cg::config
