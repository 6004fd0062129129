#include "src/blade/section_family.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <type_traits>

#include "src/algo/project_point_curve.hpp"
#include "src/core/constants.hpp"
#include "src/core/format.hpp"
#include "src/blade/periodic_seam.hpp"
#include "src/blade/section_3d.hpp"
#include "src/core/error.hpp"
#include "src/modify/transform.hpp"

namespace cg::blade::detail {
namespace {

Eigen::Matrix2d rotation(double a) {
  Eigen::Matrix2d R;
  R << std::cos(a), -std::sin(a), std::sin(a), std::cos(a);
  return R;
}

// Rotation and scale about the stacking point (plus the offset for straight vanes).
SectionProfile place_in_frame(const SectionProfile& s, const SectionPlacement& pl, const Eigen::Vector2d& stack,
                              bool with_offset) {
  const Eigen::Matrix2d A = pl.scale * rotation(pl.rotation_deg * kPi / 180);
  const Eigen::Vector2d b = stack - A * stack + (with_offset ? pl.offset : Eigen::Vector2d::Zero());
  SectionProfile r = s;
  r.curve = transformed(s.curve, A, b);  // exact: B-splines are affinely invariant
  r.le = A * s.le + b;
  r.te = A * s.te + b;
  r.chord_direction = (r.te - r.le).normalized();
  r.le_circle.centre = A * s.le_circle.centre + b;
  r.le_circle.radius *= pl.scale;
  r.te_circle.centre = A * s.te_circle.centre + b;
  r.te_circle.radius *= pl.scale;
  return r;
}

std::string section_name(std::size_t k) { return "section " + std::to_string(k); }

double wrap01(double u) { return u - std::floor(u); }

// One period of knots of a periodic curve (with multiplicities), shifted so the period starts at 0.
std::vector<double> period_knots(const BSplineCurve<2>& c) {
  const auto& U = c.knots();
  std::vector<double> k;
  for (int i = c.degree(); i < c.degree() + c.num_period_poles(); ++i)
    k.push_back(U[static_cast<std::size_t>(i)] - c.first_param());
  return k;
}

}  // namespace

// Chordwise coordinate -> parameter of one defined profile, for blending many points: the arc length
// (chordwise.hpp's exact tables) at 32 nodes per knot span, and the parameter in between by the cubic
// Hermite interpolant of t(s) (slopes 1 / |C'|): accurate to ~h^4 (far below 1e-9 of the chord at these
// node spacings), smooth, and exact at the LE (c = 0) and TE (c = +-1), which are nodes.
struct SectionFamily::ArcTable {
  std::vector<double> t, s, rate;  // node parameter, arc length from the LE, dt/ds
  double suction = 0, perimeter = 0;

  ArcTable(const SectionProfile& p) {
    const BSplineCurve<2>& c = p.curve;
    const ChordwiseMap<2> map(c, p.le_param, p.te_param);
    suction = map.suction_length();
    perimeter = map.perimeter();
    // Nodes over one period from the LE, the TE among them; every knot span cut into 32 cells.
    std::vector<double> cuts{p.le_param, map.te_param(), p.le_param + c.period()};
    for (double k : c.knots())
      for (double shift : {0.0, c.period()}) {
        const double x = k + shift;
        if (x > p.le_param && x < p.le_param + c.period()) cuts.push_back(x);
      }
    std::sort(cuts.begin(), cuts.end());
    cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
    const ArcLength<2> arc(c);
    const double at_le = arc.length_to(c.check_param(p.le_param));
    double prev_s = 0;
    for (std::size_t i = 0; i + 1 < cuts.size(); ++i)
      for (int j = 0; j < 32; ++j) {
        const double x = cuts[i] + (cuts[i + 1] - cuts[i]) * j / 32;
        add(c, arc, at_le, x, prev_s);
      }
    add(c, arc, at_le, cuts.back(), prev_s);
    s.back() = perimeter;
  }
  void add(const BSplineCurve<2>& c, const ArcLength<2>& arc, double at_le, double x, double& prev_s) {
    const double w = c.check_param(x);
    double len = arc.length_to(w) - at_le;
    if (len < prev_s - 1e-9 * perimeter) len += perimeter;  // past the curve's own seam
    len = std::max(len, prev_s);
    Eigen::Vector2d d[2];
    c.derivatives(w, 1, d);
    t.push_back(x);
    s.push_back(t.size() == 1 ? 0.0 : len);
    rate.push_back(1 / d[1].norm());
    prev_s = s.back();
  }
  double param_at(double cw) const {
    if (cw == 0) return t.front();
    const double target = cw > 0 ? cw * suction : suction + (1 + cw) * (perimeter - suction);
    const std::size_t i = static_cast<std::size_t>(
        std::clamp<std::ptrdiff_t>(std::upper_bound(s.begin(), s.end(), target) - s.begin() - 1, 0,
                                   static_cast<std::ptrdiff_t>(s.size()) - 2));
    const double h = s[i + 1] - s[i];
    if (!(h > 0)) return t[i];
    const double x = (target - s[i]) / h, h00 = (1 + 2 * x) * (1 - x) * (1 - x), h10 = x * (1 - x) * (1 - x),
                 h01 = x * x * (3 - 2 * x), h11 = x * x * (x - 1);
    return h00 * t[i] + h01 * t[i + 1] + h * (h10 * rate[i] + h11 * rate[i + 1]);
  }
};

Eigen::Vector2d stacking_point(const SectionProfile& s, StackingPoint mode) {
  switch (mode) {
    case StackingPoint::LeadingEdge: return s.le;
    case StackingPoint::TrailingEdge: return s.te;
    case StackingPoint::Centroid: return section_properties(s.curve, false).centroid;
  }
  return s.le;
}

SectionFamily::SectionFamily(const BladeDefinition& def, const std::optional<MeridionalNet>& net, double span_mm)
    : options_(def.options), net_(net), span_mm_(span_mm) {
  const bool straight = !net_.has_value();
  bool all_parametric = true;
  int points_per_side = -1;
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
    if (const auto* p = std::get_if<ParametricSectionDefinition>(&sd.shape)) {
      parametric_.push_back(*p);
      if (points_per_side >= 0 && p->points_per_side != points_per_side) all_parametric = false;
      points_per_side = p->points_per_side;
    } else {
      all_parametric = false;
    }
    profiles_.push_back(place_in_frame(raw, sd.placement, stacking_point(raw, options_.stacking), straight));
    placements_.push_back(sd.placement);
    spans_.push_back(sd.placement.span);
  }
  if (profiles_.size() == 1) {  // one section at hub and casing
    profiles_.push_back(profiles_[0]);
    placements_.push_back(placements_[0]);
    spans_ = {0.0, 1.0};
    kind_ = Kind::Single;
  } else {
    kind_ = all_parametric ? Kind::Parametric : Kind::Blended;
  }
  spline_ = SpanSpline(kind_ == Kind::Single ? std::vector<double>{0.0} : spans_);

  const double seam = options_.seam;
  if (kind_ != Kind::Blended) {
    // The seam's profile parameter, common to all slices (the LE is at 0 on every profile).
    const SectionProfile ref = kind_ == Kind::Single ? profiles_[0] : profile_at(0.5);
    if (seam == 1 || seam == -1)
      seam_param_ = ref.te_param;
    else if (seam == 0)
      seam_param_ = ref.le_param;
    else
      seam_param_ = ref.param_at_chordwise(seam);
    const BSplineCurve<2> seamed = with_seam_at(ref.curve, seam_param_);
    common_knots_ = period_knots(seamed);
    u_le_ = wrap01(ref.le_param - seam_param_);
    u_te_ = wrap01(ref.te_param - seam_param_);
    return;
  }

  // Blended: aligned shapes. u' (measured from the TE, period 1) is the pressure-side share of the
  // perimeter up to the LE and then the suction side, smoothly corrected so the LE is at the same u'
  // on every slice (see blended_point).
  double lambda_sum = 0;
  for (std::size_t k = 0; k < profiles_.size(); ++k) {
    const SectionProfile& p = profiles_[k];
    tables_.push_back(std::make_shared<const ArcTable>(p));
    double a = std::atan2(p.chord_direction.y(), p.chord_direction.x());
    if (k > 0) a += 2 * kPi * std::round((angles_.back() - a) / (2 * kPi));  // continuous twist
    angles_.push_back(a);
    stacks_.push_back(stacking_point(p, options_.stacking));
    lambdas_.push_back(1 - tables_.back()->suction / tables_.back()->perimeter);
    lambda_sum += lambdas_.back();
  }
  lambda_le_ = lambda_sum / static_cast<double>(profiles_.size());
  if (seam == 1 || seam == -1)
    u_seam_ = 0;
  else if (seam < 0)
    u_seam_ = lambda_le_ * (1 + seam);
  else
    u_seam_ = lambda_le_ + (1 - lambda_le_) * seam;
  u_le_ = wrap01(lambda_le_ - u_seam_);
  u_te_ = wrap01(-u_seam_);
}

SectionProfile SectionFamily::profile_at(double s) const {
  if (kind_ == Kind::Single) return profiles_[0];
  // Parametric: every parameter and placement value on its span spline.
  const std::vector<double> w = spline_.weights(s);
  auto blend = [&](auto get) {
    double v = 0;
    for (std::size_t k = 0; k < w.size(); ++k) v += w[k] * get(k);
    return v;
  };
  ParametricSectionDefinition d = parametric_[0];
  d.chord = blend([&](std::size_t k) { return parametric_[k].chord; });
  d.stagger_deg = blend([&](std::size_t k) { return parametric_[k].stagger_deg; });
  d.inlet_angle_deg = blend([&](std::size_t k) { return parametric_[k].inlet_angle_deg; });
  d.outlet_angle_deg = blend([&](std::size_t k) { return parametric_[k].outlet_angle_deg; });
  d.max_thickness = blend([&](std::size_t k) { return parametric_[k].max_thickness; });
  d.max_thickness_position = blend([&](std::size_t k) { return parametric_[k].max_thickness_position; });
  d.le_radius = blend([&](std::size_t k) { return parametric_[k].le_radius; });
  d.te_radius = blend([&](std::size_t k) { return parametric_[k].te_radius; });
  SectionPlacement pl;
  pl.rotation_deg = blend([&](std::size_t k) { return placements_[k].rotation_deg; });
  pl.scale = blend([&](std::size_t k) { return placements_[k].scale; });
  pl.offset = Eigen::Vector2d(blend([&](std::size_t k) { return placements_[k].offset.x(); }),
                              blend([&](std::size_t k) { return placements_[k].offset.y(); }));
  SectionProfile raw;
  try {
    require(pl.scale > 0, "the interpolated scale is " + format_number(pl.scale) + ", must be > 0");
    raw = section_from_parameters(d);
  } catch (const InvalidGeometry& e) {
    throw InvalidGeometry("the section interpolated at span " + format_number(s) + " is invalid (" + e.what() +
                          "); make the parameters of neighbouring sections vary more smoothly");
  }
  return place_in_frame(raw, pl, stacking_point(raw, options_.stacking), straight());
}

FamilySlice SectionFamily::slice(double s) const {
  FamilySlice f;
  f.family_ = this;
  f.span_ = s;
  if (kind_ != Kind::Blended) {
    const SectionProfile p = profile_at(s);
    f.curve_ = with_seam_at(p.curve, seam_param_);
    f.le_ = p.le;
    f.te_ = p.te;
    f.stack_ = stacking_point(p, options_.stacking);
  } else {
    f.weights_ = spline_.weights(s);
    f.lambda_ = 0;
    for (std::size_t k = 0; k < f.weights_.size(); ++k) {
      f.angle_ += f.weights_[k] * angles_[k];
      f.stack_ += f.weights_[k] * stacks_[k];
      f.lambda_ += f.weights_[k] * lambdas_[k];
    }
    // The correction d sin^2(pi t) / sin^2(pi lambda) of blended_point must keep u'(t) increasing.
    const double sl = std::sin(kPi * f.lambda_), d = lambda_le_ - f.lambda_;
    require(f.lambda_ > 0.05 && f.lambda_ < 0.95 && std::abs(d) * kPi < 0.9 * sl * sl,
            "the sections blended at span " + format_number(s) +
                " differ too much in the length ratio of their pressure and suction sides");
    f.le_ = blended_point(f, u_le_);
    f.te_ = blended_point(f, u_te_);
  }
  place(f);
  return f;
}

Eigen::Vector2d SectionFamily::blended_point(const FamilySlice& f, double u) const {
  // u' from the TE; t = pressure-side arc fraction then suction side: c = t / lambda - 1 for t <= lambda,
  // (t - lambda) / (1 - lambda) beyond. u'(t) = t + d sin^2(pi t) / sin^2(pi lambda), d = lambda_le -
  // lambda: smooth and periodic, u'(lambda) = lambda_le, so the LE is at the same u' on every slice
  // while the parameter speed stays continuous across LE and TE.
  const double up = wrap01(u + u_seam_), lam = f.lambda_;
  const double sl2 = std::sin(kPi * lam) * std::sin(kPi * lam), d = lambda_le_ - lam;
  double t = up, lo = 0, hi = 1;
  for (int it = 0; it < 60; ++it) {
    const double g = t + d * std::sin(kPi * t) * std::sin(kPi * t) / sl2 - up;
    if (std::abs(g) <= 1e-15) break;
    (g > 0 ? hi : lo) = t;
    const double dg = 1 + d * kPi * std::sin(2 * kPi * t) / sl2;
    double tn = t - g / dg;
    if (!(tn > lo && tn < hi)) tn = 0.5 * (lo + hi);
    t = tn;
  }
  const double c = up == 0 ? 1.0 : t <= lam ? std::max(-1.0, t / lam - 1) : std::min(1.0, (t - lam) / (1 - lam));
  Eigen::Vector2d q = Eigen::Vector2d::Zero();
  for (std::size_t k = 0; k < f.weights_.size(); ++k) {
    if (f.weights_[k] == 0) continue;
    const Eigen::Vector2d pk = profiles_[k].curve.point(tables_[k]->param_at(c));
    q += f.weights_[k] * (rotation(-angles_[k]) * (pk - stacks_[k]));
  }
  return f.stack_ + rotation(f.angle_) * q;
}

void SectionFamily::place(FamilySlice& f) const {
  const double s = f.span_;
  const std::string name = "the section at span " + format_number(s);
  if (!net_) {
    f.z_ = s * span_mm_;
    if (f.curve_) f.exact_3d_ = section_in_plane(*f.curve_, f.z_);
    return;
  }
  const SpanSpline& sp = spline_;
  auto value = [&](auto get) {
    std::vector<double> y;
    for (std::size_t k = 0; k < sp.size(); ++k) y.push_back(get(placements_[k]));
    return sp.value(y, s);
  };
  f.theta0_ = value([](const SectionPlacement& p) { return p.theta_deg; }) * kPi / 180;
  f.offset_ = Eigen::Vector2d(value([](const SectionPlacement& p) { return p.offset.x(); }),
                              value([](const SectionPlacement& p) { return p.offset.y(); }));
  const MeridionalNet& net = *net_;
  f.line_ = std::make_shared<const Streamline>(net.streamline_at(s));
  const Streamline& line = *f.line_;
  const StationCutResult le = cut_station(net.leading_edge()->curve, line);
  require(le.found, name + ": the leading-edge line does not cut its streamline");
  f.mp_le_ = line.m_prime(le.cut.streamline_param);
  f.r_ref_ = le.cut.point.y();
  f.k_scale_ = 1;  // section mm -> mm at r_ref
  if (net.trailing_edge()) {
    const StationCutResult te = cut_station(net.trailing_edge()->curve, line);
    require(te.found, name + ": the trailing-edge line does not cut its streamline");
    const double mp_te = line.m_prime(te.cut.streamline_param);
    require(mp_te > f.mp_le_, name + ": the trailing-edge line must lie downstream of the leading-edge line");
    const double da = f.te_.x() - f.le_.x();
    require(da > 1e-9 * (f.te_ - f.le_).norm(),
            name + ": the section's TE must lie downstream (+a) of its LE to be fitted between the LE/TE lines");
    f.k_scale_ = (mp_te - f.mp_le_) * f.r_ref_ / da;
  }
  f.a_le_ = f.le_.x();
  f.b_stack_ = f.stack_.y();
}

Eigen::Vector3d FamilySlice::place(const Eigen::Vector2d& q) const {
  if (!line_) return Eigen::Vector3d(q.x(), q.y(), z_);
  const double mp = mp_le_ + (k_scale_ * (q.x() - a_le_) + offset_.x()) / r_ref_;
  const double theta = theta0_ + (k_scale_ * (q.y() - b_stack_) + offset_.y()) / r_ref_;
  double u = 0;
  try {
    u = line_->param_at_m_prime(mp);
  } catch (const InvalidGeometry& e) {
    throw InvalidGeometry("the section at span " + format_number(span_) +
                          " extends beyond its streamline; extend the hub/casing contours upstream or downstream (" +
                          e.what() + ")");
  }
  const Eigen::Vector2d xr = line_->point(u);
  return Eigen::Vector3d(xr.x(), xr.y() * std::cos(theta), xr.y() * std::sin(theta));
}

std::vector<Eigen::Vector2d> FamilySlice::unplace(const std::vector<Eigen::Vector3d>& pts) const {
  std::vector<Eigen::Vector2d> out;
  if (!line_) {
    for (const auto& p : pts) out.push_back(p.head<2>());
    return out;
  }
  CurveProjector<2> proj(line_->curve());
  for (const auto& p : pts) {
    const CurveProjection<2> foot = proj.project(Eigen::Vector2d(p.x(), std::hypot(p.y(), p.z())));
    const double mp = line_->m_prime(foot.param);
    const double theta = std::remainder(std::atan2(p.z(), p.y()) - theta0_, 2 * kPi);
    out.emplace_back(a_le_ + (r_ref_ * (mp - mp_le_) - offset_.x()) / k_scale_,
                     b_stack_ + (r_ref_ * theta - offset_.y()) / k_scale_);
  }
  return out;
}

std::vector<Eigen::Vector2d> FamilySlice::points_2d(const std::vector<double>& u) const {
  std::vector<Eigen::Vector2d> out(u.size());
  for (std::size_t i = 0; i < u.size(); ++i)
    out[i] = curve_ ? curve_->point(wrap01(u[i])) : family_->blended_point(*this, u[i]);
  return out;
}

std::vector<Eigen::Vector3d> FamilySlice::points_3d(const std::vector<double>& u) const {
  std::vector<Eigen::Vector3d> out(u.size());
  if (exact_3d_) {
    for (std::size_t i = 0; i < u.size(); ++i) out[i] = exact_3d_->point(wrap01(u[i]));
    return out;
  }
  const std::vector<Eigen::Vector2d> q = points_2d(u);
  for (std::size_t i = 0; i < u.size(); ++i) out[i] = place(q[i]);
  return out;
}

}  // namespace cg::blade::detail
