#include "src/blade/blade_surface.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <type_traits>

#include "src/blade/format.hpp"
#include "src/blade/section_3d.hpp"
#include "src/core/error.hpp"
#include "src/fit/skin.hpp"
#include "src/modify/transform.hpp"

namespace cg::blade {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Largest distance of a stream-surface section curve from the exactly placed section, mm.
constexpr double kStreamSectionTolerance = 1e-6;

using detail::fmt;

Eigen::Vector2d stacking_point(const SectionProfile& s, StackingPoint mode) {
  switch (mode) {
    case StackingPoint::LeadingEdge: return s.le;
    case StackingPoint::TrailingEdge: return s.te;
    case StackingPoint::Centroid: return section_properties(s.curve).centroid;
  }
  return s.le;
}

// Rotation and scale about the stacking point (plus the offset for straight vanes).
SectionProfile place_in_frame(const SectionProfile& s, const SectionPlacement& pl, const Eigen::Vector2d& stack,
                              bool with_offset) {
  const double a = pl.rotation_deg * kPi / 180;
  Eigen::Matrix2d A;
  A << std::cos(a), -std::sin(a), std::sin(a), std::cos(a);
  A *= pl.scale;
  const Eigen::Vector2d b = stack - A * stack + (with_offset ? pl.offset : Eigen::Vector2d::Zero());
  SectionProfile r = s;
  r.curve = transformed(s.curve, A, b);  // exact: B-splines are affinely invariant
  r.le = A * s.le + b;
  r.te = A * s.te + b;
  return r;
}

std::string section_name(std::size_t k) { return "section " + std::to_string(k); }

}  // namespace

double surface_u_at_chordwise(double c, double u_te) {
  require(c >= -1 && c <= 1, "chordwise coordinate must be in [-1, 1], got " + fmt(c));
  return c >= 0 ? c * u_te : u_te + (1 + c) * (1 - u_te);  // exact u_te at c = +-1
}

double chordwise_at_surface_u(double u, double u_te) {
  u -= std::floor(u);
  return u <= u_te ? u / u_te : -(1 - u) / (1 - u_te);
}

BladeModel build_blade(const BladeDefinition& def) {
  const BladeOptions& opt = def.options;
  require(opt.overbuild > 0 && opt.overbuild <= 0.5, "blade options: overbuild must be in (0, 0.5] of span, got " +
                                                         fmt(opt.overbuild));
  require(opt.chordwise_samples >= 8 && opt.chordwise_samples <= 2000,
          "blade options: chordwise_samples must be in [8, 2000], got " + std::to_string(opt.chordwise_samples));
  require(!def.sections.empty(), "blade: at least one section is needed");
  for (std::size_t k = 0; k < def.sections.size(); ++k) {
    const SectionPlacement& p = def.sections[k].placement;
    require(p.span >= 0 && p.span <= 1, section_name(k) + ": span must be in [0, 1], got " + fmt(p.span));
    require(k == 0 || p.span > def.sections[k - 1].placement.span,
            section_name(k) + ": section spans must increase strictly, got " + fmt(p.span) + " after " +
                fmt(def.sections[k - 1].placement.span));
    require(p.scale > 0, section_name(k) + ": scale must be > 0, got " + fmt(p.scale));
  }

  BladeModel model;
  model.options = opt;
  const bool straight = std::holds_alternative<StraightFlowPath>(def.flow_path);
  double span_mm = 0;
  if (straight) {
    span_mm = std::get<StraightFlowPath>(def.flow_path).span;
    require(span_mm > 0, "straight vane: span must be > 0 mm, got " + fmt(span_mm));
    model.trim.straight = true;
    model.trim.hub_z = 0;
    model.trim.casing_z = span_mm;
    model.span_length = span_mm;
  } else {
    model.net.emplace(std::get<MeridionalFlowPath>(def.flow_path).net);
    require(model.net->leading_edge().has_value(),
            "meridional blade: the net needs a leading-edge line to place the sections");
    model.trim.straight = false;
    model.trim.hub = model.net->hub().curve();
    model.trim.casing = model.net->casing().curve();
    const auto& cuts = model.net->leading_edge()->cuts;
    model.span_length = (cuts.back().point - cuts.front().point).norm();
  }

  // 2D profiles and their spans (a single section is used at hub and casing).
  struct Placed {
    SectionProfile profile;
    Eigen::Vector2d stack;
    const SectionPlacement* placement;
    double span;
  };
  std::vector<Placed> placed;
  for (std::size_t k = 0; k < def.sections.size(); ++k) {
    const BladeSectionDefinition& sd = def.sections[k];
    SectionProfile raw;
    try {
      raw = std::visit(
          [](const auto& shape) {
            if constexpr (std::is_same_v<std::decay_t<decltype(shape)>, PointSectionDefinition>)
              return section_from_points(shape);
            else
              return section_from_parameters(shape);
          },
          sd.shape);
    } catch (const InvalidGeometry& e) {
      throw InvalidGeometry(section_name(k) + ": " + e.what());
    }
    const Eigen::Vector2d stack = stacking_point(raw, opt.stacking);
    SectionProfile p = place_in_frame(raw, sd.placement, stack, straight);
    placed.push_back({p, stack, &sd.placement, sd.placement.span});
  }
  if (placed.size() == 1) {
    placed[0].span = 0;
    placed.push_back(placed[0]);
    placed[1].span = 1;
  }

  // The TE parameter: sections from parameters have it at 0.5, one point section at its own value;
  // several point sections with different values share their mean (see blade_surface.hpp).
  double u_te = 0;
  for (const Placed& p : placed) u_te += p.profile.te_param;
  u_te /= static_cast<double>(placed.size());

  // 3D section curves: exact in the plane z = span * span_mm (straight vane); on the stream surface
  // interpolated to kStreamSectionTolerance (the map (a, b) -> (x, r cos theta, r sin theta) is not
  // rational).
  std::vector<BSplineCurve<3>> sections;
  for (std::size_t k = 0; k < placed.size(); ++k) {
    const Placed& p = placed[k];
    if (straight) {
      sections.push_back(detail::section_in_plane(p.profile.curve, p.span * span_mm));
      continue;
    }
    const std::string name = section_name(std::min(k, def.sections.size() - 1)) + " (span " + fmt(p.span) + ")";
    const MeridionalNet& net = *model.net;
    const Streamline line = net.streamline_at(p.span);
    const StationCutResult le = cut_station(net.leading_edge()->curve, line);
    require(le.found, name + ": the leading-edge line does not cut its streamline");
    const double mp_le = line.m_prime(le.cut.streamline_param), r_ref = le.cut.point.y();
    double k_scale = 1;  // section mm -> mm at r_ref
    if (net.trailing_edge()) {
      const StationCutResult te = cut_station(net.trailing_edge()->curve, line);
      require(te.found, name + ": the trailing-edge line does not cut its streamline");
      const double mp_te = line.m_prime(te.cut.streamline_param);
      require(mp_te > mp_le, name + ": the trailing-edge line must lie downstream of the leading-edge line");
      const double da = p.profile.te.x() - p.profile.le.x();
      require(da > 1e-9 * p.profile.chord(),
              name + ": the section's TE must lie downstream (+a) of its LE to be fitted between the LE/TE lines");
      k_scale = (mp_te - mp_le) * r_ref / da;
    }
    const Eigen::Vector2d stack = stacking_point(p.profile, opt.stacking);
    const double theta0 = p.placement->theta_deg * kPi / 180;
    const auto on_stream_surface = [&](const Eigen::Vector2d& q) {
      const double mp = mp_le + (k_scale * (q.x() - p.profile.le.x()) + p.placement->offset.x()) / r_ref;
      const double theta = theta0 + (k_scale * (q.y() - stack.y()) + p.placement->offset.y()) / r_ref;
      double u = 0;
      try {
        u = line.param_at_m_prime(mp);
      } catch (const InvalidGeometry& e) {
        throw InvalidGeometry(name + " extends beyond its streamline; extend the hub/casing contours upstream or "
                                     "downstream (" + e.what() + ")");
      }
      const Eigen::Vector2d xr = line.point(u);
      return Eigen::Vector3d(xr.x(), xr.y() * std::cos(theta), xr.y() * std::sin(theta));
    };
    sections.push_back(detail::map_closed_section(p.profile.curve, on_stream_surface, kStreamSectionTolerance,
                                                  2 * opt.chordwise_samples)
                           .curve);
  }

  // Skinning (The NURBS Book 10.3, src/fit/skin.hpp): the sections become iso-curves v = span exactly.
  // The over-build sections extrapolate the two end sections linearly, pole by pole in homogeneous
  // form, which needs them compatible first.
  std::vector<double> spans;
  for (const Placed& p : placed) spans.push_back(p.span);
  sections = make_compatible(sections);
  const auto extrapolate = [&](std::size_t a, std::size_t b, double v) {
    const double w = (v - spans[a]) / (spans[b] - spans[a]);
    const BSplineCurve<3>& A = sections[a];
    auto h = ((1 - w) * A.homogeneous_poles() + w * sections[b].homogeneous_poles()).eval();
    return BSplineCurve<3>::from_homogeneous(A.degree(), A.knots(), std::move(h), A.is_periodic());
  };
  std::vector<BSplineCurve<3>> rows;
  rows.push_back(extrapolate(0, 1, -opt.overbuild));
  rows.insert(rows.end(), sections.begin(), sections.end());
  rows.push_back(extrapolate(sections.size() - 2, sections.size() - 1, 1 + opt.overbuild));
  std::vector<double> vs{-opt.overbuild};
  vs.insert(vs.end(), spans.begin(), spans.end());
  vs.push_back(1 + opt.overbuild);
  SkinOptions so;
  so.degree_v = 3;
  so.v_params = vs;
  model.surface = skin(rows, so).surface;
  model.u_te = u_te;
  for (std::size_t k = 0; k < placed.size(); ++k) {
    model.section_spans.push_back(placed[k].span);
    model.profiles.push_back(placed[k].profile);
    model.section_curves.push_back(sections[k]);
  }
  return model;
}

}  // namespace cg::blade
