#include "src/blade/meridional_net.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

#include "src/algo/intersect_curves.hpp"
#include "src/blade/planar_polyline.hpp"
#include "src/core/format.hpp"
#include "src/core/curve_evaluator.hpp"
#include "src/core/error.hpp"
#include "src/fit/interpolate.hpp"

namespace cg::blade {
namespace {


std::string span_name(double span) { return "streamline at span " + format_number(span); }

// Smallest radius on the curve, sampled densely per knot span (r is a polynomial of degree p per span;
// 32 samples per span resolve any dip that matters for the quadrature of dm / r).
double min_radius(const BSplineCurve<2>& c) {
  double r = std::numeric_limits<double>::infinity();
  CurveEvaluator<2> ev(c);
  for (double u : detail::sample_params(c, 32)) r = std::min(r, ev.point(u).y());
  return r;
}

}  // namespace

BSplineCurve<2> meridional_curve(const MeridionalPolyline& points, const char* what) {
  require(points.size() >= 2, std::string(what) + ": needs at least 2 points (x, r), got " +
                                  std::to_string(points.size()));
  for (std::size_t i = 0; i + 1 < points.size(); ++i)
    require((points[i + 1] - points[i]).norm() > 1e-9, std::string(what) + ": points " + std::to_string(i) + " and " +
                                                           std::to_string(i + 1) + " coincide");
  const int degree = std::min(3, static_cast<int>(points.size()) - 1);
  return interpolate<2>(points, degree, ParamMethod::ChordLength);
}

Streamline::Streamline(BSplineCurve<2> curve, double span) : curve_(std::move(curve)), span_(span) {
  const double rmin = min_radius(curve_);
  require(rmin > 0, span_name(span) + ": radius must be > 0 everywhere, minimum is " + format_number(rmin) + " mm");
  m_ = detail::CurveIntegral(curve_, curve_.first_param(), curve_.last_param(), detail::Integrand::ArcLength);
  mp_ = detail::CurveIntegral(curve_, curve_.first_param(), curve_.last_param(),
                              detail::Integrand::ArcLengthOverRadius);
}

double Streamline::meridional_length(double u) const { return m_.at(curve_, curve_.check_param(u)); }
double Streamline::m_prime(double u) const { return mp_.at(curve_, curve_.check_param(u)); }

double Streamline::param_at_m_prime(double m_prime) const {
  const double tol = 1e-12 * (1.0 + mp_.total());
  if (!(m_prime >= -tol && m_prime <= mp_.total() + tol)) {  // (message built only on failure: hot path)
    const ValueRangeText t = format_value_range(m_prime, 0, mp_.total());
    throw InvalidGeometry(span_name(span_) + ": m' = " + t.value + " is outside the streamline, allowed [0, " + t.hi + "]");
  }
  return mp_.inverse(curve_, m_prime);
}

double Streamline::param_at_length(double m) const {
  const double tol = 1e-12 * (1.0 + m_.total());
  if (!(m >= -tol && m <= m_.total() + tol)) {
    const ValueRangeText t = format_value_range(m, 0, m_.total());
    throw InvalidGeometry(span_name(span_) + ": m = " + t.value + " mm is outside the streamline, allowed [0, " + t.hi + "]");
  }
  return m_.inverse(curve_, m);
}

StationCutResult cut_station(const BSplineCurve<2>& station, const Streamline& streamline) {
  const CurveCurveIntersections x = intersect_curves(streamline.curve(), station);
  require(x.overlaps.empty(), "station runs along the " + span_name(streamline.span()) +
                                  " instead of cutting it; it must cut every streamline exactly once");
  StationCutResult r;
  if (x.points.empty()) return r;
  require(x.points.size() == 1, "station cuts the " + span_name(streamline.span()) + " " +
                                    std::to_string(x.points.size()) + " times; it must cut every streamline exactly once");
  r.found = true;
  r.cut = {x.points.front().s, x.points.front().t, x.points.front().point};
  return r;
}

MeridionalNet::MeridionalNet(const MeridionalNetDefinition& def) : samples_(def.samples) {
  require(def.samples >= 16 && def.samples <= 100000,
          "meridional net: samples must be in [16, 100000], got " + std::to_string(def.samples));
  require(def.streamlines.size() == def.streamline_spans.size(),
          "meridional net: streamline_spans must give one span per explicit streamline (" +
              std::to_string(def.streamlines.size()) + " streamlines, " + std::to_string(def.streamline_spans.size()) +
              " spans)");
  streamlines_.emplace_back(meridional_curve(def.hub, "hub contour"), 0.0);
  double prev = 0;
  for (std::size_t k = 0; k < def.streamlines.size(); ++k) {
    const double s = def.streamline_spans[k];
    require(s > prev && s < 1, "meridional net: streamline span " + format_number(s) +
                                   " must lie in (0, 1) and increase strictly (previous " + format_number(prev) + ")");
    const std::string name = span_name(s);
    streamlines_.emplace_back(meridional_curve(def.streamlines[k], name.c_str()), s);
    prev = s;
  }
  streamlines_.emplace_back(meridional_curve(def.casing, "casing contour"), 1.0);

  // Every neighbouring pair: no crossing of the sampled curves, and all pairs on the same side
  // (the sign of the casing side relative to the hub, measured at mid-length).
  auto side = [](const Streamline& lo, const Streamline& hi) {
    const double u = lo.param_at_length(0.5 * lo.total_length());
    Eigen::Vector2d d[2];
    lo.curve().derivatives(u, 1, d);
    // Nearest sample of the upper streamline to the mid point.
    Eigen::Vector2d best = hi.point(hi.first_param());
    for (double v : detail::sample_params(hi.curve(), 16))
      if ((hi.point(v) - d[0]).norm() < (best - d[0]).norm()) best = hi.point(v);
    const Eigen::Vector2d w = best - d[0];
    return d[1].x() * w.y() - d[1].y() * w.x();
  };
  auto check_pair = [&](const Streamline& lo, const Streamline& hi, double sign) {
    const CurveCurveIntersections x = intersect_curves(lo.curve(), hi.curve());
    const bool crossing = !x.points.empty() || !x.overlaps.empty();
    require(!crossing && side(lo, hi) * sign > 0,
            "meridional net: the " + span_name(lo.span()) + " and the " + span_name(hi.span()) +
                " touch or cross; streamlines must be ordered hub to casing without crossing");
  };
  const double sign = side(streamlines_.front(), streamlines_.back()) > 0 ? 1.0 : -1.0;
  for (std::size_t k = 0; k + 1 < streamlines_.size(); ++k) check_pair(streamlines_[k], streamlines_[k + 1], sign);

  std::vector<double> spans;
  for (const Streamline& l : streamlines_) {
    spans.push_back(l.span());
    std::vector<Eigen::Vector2d> pts(static_cast<std::size_t>(samples_));
    for (int i = 0; i < samples_; ++i)
      pts[static_cast<std::size_t>(i)] = l.point(l.param_at_length(l.total_length() * i / (samples_ - 1)));
    defining_points_.push_back(std::move(pts));
  }
  defining_ = detail::SpanSpline(spans);

  for (double s : def.interpolated_spans) {
    require(s > 0 && s < 1, "meridional net: interpolated span " + format_number(s) + " must lie in (0, 1)");
    if (std::any_of(streamlines_.begin(), streamlines_.end(),
                    [&](const Streamline& l) { return std::abs(l.span() - s) <= 1e-12; }))
      continue;
    Streamline l = streamline_at(s);
    auto it = std::lower_bound(streamlines_.begin(), streamlines_.end(), s,
                               [](const Streamline& a, double v) { return a.span() < v; });
    streamlines_.insert(it, std::move(l));
  }

  auto make_station = [&](const MeridionalPolyline& pts, const std::string& name) {
    QuasiOrthogonal q;
    q.curve = meridional_curve(pts, name.c_str());
    for (const Streamline& l : streamlines_) {
      const StationCutResult c = cut_station(q.curve, l);
      require(c.found, name + " does not reach the " + span_name(l.span()) +
                           "; it must run from hub to casing and cut every streamline once");
      q.cuts.push_back(c.cut);
    }
    return q;
  };
  if (!def.leading_edge.empty()) leading_edge_ = make_station(def.leading_edge, "leading-edge line");
  if (!def.trailing_edge.empty()) trailing_edge_ = make_station(def.trailing_edge, "trailing-edge line");
  for (std::size_t k = 0; k < def.stations.size(); ++k)
    stations_.push_back(make_station(def.stations[k], "station " + std::to_string(k)));
}

Streamline MeridionalNet::streamline_at(double span) const {
  for (const Streamline& l : streamlines_)
    if (std::abs(l.span() - span) <= 1e-12) return l;
  const std::vector<double> w = defining_.weights(span);
  std::vector<Eigen::Vector2d> pts(static_cast<std::size_t>(samples_), Eigen::Vector2d::Zero());
  for (std::size_t k = 0; k < w.size(); ++k)
    for (std::size_t i = 0; i < pts.size(); ++i) pts[i] += w[k] * defining_points_[k][i];
  const std::string name = span_name(span);
  return Streamline(meridional_curve(pts, name.c_str()), span);
}

}  // namespace cg::blade
