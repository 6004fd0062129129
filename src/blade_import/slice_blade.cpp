#include "src/blade_import/slice_blade.hpp"

#include <algorithm>
#include <cmath>

#include "src/blade/planar_polyline.hpp"
#include "src/blade/section_family.hpp"
#include "src/blade_import/channel_side.hpp"
#include "src/core/constants.hpp"
#include "src/core/error.hpp"
#include "src/core/format.hpp"

namespace cg::blade_import {
namespace {

// The casing the blade's tip follows: the file's casing moved inwards (along its normal) by the tip
// gap, interpolated linearly in x between the tip section's LE and TE and constant beyond.
std::vector<Eigen::Vector2d> tip_contour(const ImportedBlade& b) {
  std::vector<Eigen::Vector2d> c = b.casing;
  if (b.tip_gap_le == 0 && b.tip_gap_te == 0) return c;
  if (b.kind == RowKind::Cascade) {
    if (std::abs(b.tip_gap_le - b.tip_gap_te) > 1e-9)
      throw InvalidGeometry(b.file + ":" + std::to_string(b.casing_line) +
                            ": a cascade's tip gap must be the same at LE and TE (its casing is a plane)");
    for (auto& p : c) p.y() -= b.tip_gap_le;
    return c;
  }
  const ImportedSection& tip = b.sections.back();
  const double x_le = tip.suction.front().x(), x_te = tip.suction.back().x();
  std::vector<Eigen::Vector2d> out;
  for (std::size_t i = 0; i < c.size(); ++i) {
    const Eigen::Vector2d t = (c[std::min(i + 1, c.size() - 1)] - c[i == 0 ? 0 : i - 1]).normalized();
    Eigen::Vector2d n(-t.y(), t.x());
    if (n.y() > 0) n = -n;  // towards the axis (inwards)
    const double f = std::clamp((c[i].x() - x_le) / (x_te - x_le), 0.0, 1.0);
    out.push_back(c[i] + ((1 - f) * b.tip_gap_le + f * b.tip_gap_te) * n);
  }
  return out;
}

[[noreturn]] void not_reaching(const ImportedBlade& b, bool hub, double by) {
  const std::size_t k = hub ? 0 : b.sections.size() - 1;
  throw InvalidGeometry(b.file_of(k) + ":" + std::to_string(b.sections[k].line) + ": section " + std::to_string(k + 1) +
                        " does not reach the " + (hub ? "hub" : (b.tip_gap_le > 0 || b.tip_gap_te > 0 ? "casing less the tip gap" : "casing")) +
                        ": it lies up to " + format_number(std::abs(by)) +
                        " mm inside the flow path; the first and last sections must reach to or past hub and casing");
}

// Spanwise parameter of the input surface where chordwise sample j meets the stream surface at s, at
// or above section `from` (the cut of the previous, lower span; the root moves up with s). An end
// section short of hub or casing by at most `reach` (mm; a CAD blade's cuts just inside its end faces)
// is continued by the surface's linear extension beyond it.
double cut_tau(const ImportedBlade& b, const InputSurface& surf, ChannelSide& side, int j, double s, std::size_t& from,
               double reach) {
  const std::size_t K = surf.sections();
  auto f_at = [&](std::size_t k) { return side.offset(surf.point(j, surf.section_tau(k)), s); };
  std::size_t k = from;
  double fa = f_at(k);
  while (k > 0 && fa > 0) fa = f_at(--k);
  double a = surf.section_tau(k);
  if (fa > 0) {  // the hub section lies above the stream surface
    if (fa > reach) not_reaching(b, true, fa);
    a -= surf.section_tau(1) - surf.section_tau(0);
    fa = side.offset(surf.point(j, a), s);
    if (fa > 0) not_reaching(b, true, fa);
  }
  double fc = f_at(k + 1);
  while (fc < 0 && k + 2 < K) {
    ++k;
    a = surf.section_tau(k);
    fa = fc;
    fc = f_at(k + 1);
  }
  from = k;
  double c = surf.section_tau(k + 1);
  if (fc < 0) {  // the tip section lies below the stream surface
    if (-fc > reach) not_reaching(b, false, fc);
    c += surf.section_tau(K - 1) - surf.section_tau(K - 2);
    fc = side.offset(surf.point(j, c), s);
    if (fc < 0) not_reaching(b, false, fc);
  }
  if (fa == 0) return a;
  int last_side = 0;
  for (int it = 0; it < 100; ++it) {  // Illinois regula falsi
    const double t = (a * fc - c * fa) / (fc - fa);
    const double ft = side.offset(surf.point(j, t), s);
    if (std::abs(ft) < 1e-11 || std::abs(c - a) < 1e-13 * std::abs(c)) return t;
    if ((ft > 0) == (fc > 0)) {
      c = t, fc = ft;
      if (last_side == -1) fa /= 2;
      last_side = -1;
    } else {
      a = t, fa = ft;
      if (last_side == 1) fc /= 2;
      last_side = 1;
    }
  }
  return (a * fc - c * fa) / (fc - fa);
}

// A cut in its section frame as a point section, placed back where it was cut.
// The LE and TE are the file's: where its suction and pressure sides meet (samples 0 and M).
blade::BladeSectionDefinition section_of_cut(const ImportedBlade& b, std::vector<Eigen::Vector2d> ab, double s,
                                             double theta_ref, const blade::BladeOptions& options) {
  blade::BladeSectionDefinition sd;
  blade::PointSectionDefinition p;
  p.le_index = 0;
  p.te_index = static_cast<int>(ab.size() / 2);
  p.points = std::move(ab);
  p.suction_side = blade::detail::polygon_signed_area(p.points) > 0 ? blade::SuctionSide::CounterClockwise : blade::SuctionSide::Clockwise;
  blade::SectionProfile raw;
  try {
    raw = blade::section_from_points(p);
  } catch (const Error& e) {
    throw InvalidGeometry(b.file + ": the blade cut at span " + format_number(s) + ": " + e.what());
  }
  sd.placement.span = s;
  if (b.kind == RowKind::Annular) {
    const Eigen::Vector2d stack = blade::detail::stacking_point(raw, options.stacking);
    sd.placement.offset = Eigen::Vector2d(raw.le.x(), stack.y());
    sd.placement.theta_deg = theta_ref * 180 / kPi;
  }
  sd.shape = std::move(p);
  return sd;
}

}  // namespace

SlicedBlade slice_blade(const ImportedBlade& b, const ImportOptions& o, const blade::BladeOptions& options,
                        const blade::MeridionalNetDefinition* channel) {
  SlicedBlade out;
  std::size_t most = 0;
  for (const auto& s : b.sections) most = std::max({most, s.suction.size(), s.pressure.size()});
  const int m = o.samples_per_side > 0 ? o.samples_per_side : std::clamp(static_cast<int>(2 * most), 96, 300);
  out.surface = std::make_shared<const InputSurface>(b, m, o.tolerance);
  const InputSurface& surf = *out.surface;
  const int n = cut_count(o, b.sections.size());
  for (int i = 0; i < n; ++i) out.spans.push_back(static_cast<double>(i) / (n - 1));

  blade::MeridionalNetDefinition net_def;
  if (channel) {  // its streamlines and sampling; the LE line is the import's
    net_def = *channel;
    net_def.leading_edge.clear();
    net_def.trailing_edge.clear();
    net_def.stations.clear();
  }
  const std::vector<Eigen::Vector2d> casing = tip_contour(b);
  std::optional<ChannelSide> side;
  double span = 0;
  if (b.kind == RowKind::Cascade) {
    span = casing.front().y();
    require(span > 0, b.file + ":" + std::to_string(b.casing_line) + ": the casing (less the tip gap) must lie above the hub");
    side.emplace(span);
  } else {
    net_def.hub = b.hub;
    net_def.casing = casing;
    try {
      side.emplace(blade::MeridionalNet(net_def));
    } catch (const InvalidGeometry& e) {
      throw InvalidGeometry(b.file + ":" + std::to_string(b.hub_line) + ": the CHANNEL's hub and shroud: " + e.what());
    }
  }
  std::vector<std::vector<Eigen::Vector3d>> cuts(out.spans.size());
  std::vector<std::size_t> from(static_cast<std::size_t>(surf.loop_size()), 0);
  for (std::size_t i = 0; i < out.spans.size(); ++i)
    for (int j = 0; j < surf.loop_size(); ++j)
      cuts[i].push_back(surf.point(j, cut_tau(b, surf, *side, j, out.spans[i], from[static_cast<std::size_t>(j)], o.tolerance)));

  if (b.kind == RowKind::Cascade) {
    out.definition.flow_path = blade::StraightFlowPath{span};
    for (std::size_t i = 0; i < cuts.size(); ++i) {
      std::vector<Eigen::Vector2d> ab;
      for (const auto& p : cuts[i]) ab.push_back(p.head<2>());
      out.definition.sections.push_back(section_of_cut(b, std::move(ab), out.spans[i], 0, options));
    }
    out.definition.options = options;
    return out;
  }
  // The LE line through the cuts' first points, continued straight past hub and casing.
  const double ext = (options.overbuild + 0.1) * static_cast<double>(n - 1);
  auto xr = [](const Eigen::Vector3d& p) { return Eigen::Vector2d(p.x(), std::hypot(p.y(), p.z())); };
  net_def.leading_edge.push_back(xr(cuts[0][0]) + ext * (xr(cuts[0][0]) - xr(cuts[1][0])));
  for (const auto& c : cuts) net_def.leading_edge.push_back(xr(c[0]));
  net_def.leading_edge.push_back(xr(cuts[n - 1][0]) + ext * (xr(cuts[n - 1][0]) - xr(cuts[n - 2][0])));
  blade::MeridionalNet net(net_def);
  const double theta_ref = std::atan2(cuts[0][0].z(), cuts[0][0].y());
  for (std::size_t i = 0; i < cuts.size(); ++i) {
    const blade::Streamline line = net.streamline_at(out.spans[i]);
    const blade::StationCutResult le = blade::cut_station(net.leading_edge()->curve, line);
    require(le.found, b.file + ": the LE line misses the streamline at span " + format_number(out.spans[i]));
    const double mp_le = line.m_prime(le.cut.streamline_param), r_ref = le.cut.point.y();
    CurveProjector<2> proj(line.curve());
    std::vector<Eigen::Vector2d> ab;
    for (const auto& p : cuts[i]) {
      const double mp = line.m_prime(proj.project(xr(p)).param);
      ab.emplace_back(r_ref * (mp - mp_le), r_ref * std::remainder(std::atan2(p.z(), p.y()) - theta_ref, 2 * kPi));
    }
    out.definition.sections.push_back(section_of_cut(b, std::move(ab), out.spans[i], theta_ref, options));
  }
  out.definition.flow_path = blade::MeridionalFlowPath{net_def};
  out.definition.options = options;
  return out;
}

}  // namespace cg::blade_import
