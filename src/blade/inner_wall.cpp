#include "src/blade/inner_wall.hpp"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <memory>
#include <optional>
#include <utility>

#include "src/core/constants.hpp"
#include "src/core/format.hpp"
#include "src/core/knots.hpp"
#include "src/core/parallel.hpp"
#include "src/fit/approximate.hpp"
#include "src/fit/skin.hpp"

namespace cg::blade {
namespace {

using Vec3 = Eigen::Vector3d;

}  // namespace

Vec3 inner_wall_point(const BladeCoordinates& coords, const ThicknessField& thickness, double span, double chord,
                      ChordAccuracy accuracy) {
  const BladeFrame f = coords.frame(span, chord, accuracy);
  return f.point - thickness.at(span, chord) * f.normal;
}

namespace {

// ---------------------------------------------------------------------------------------------------
// Crease (trailing-edge crossing of the suction- and pressure-side offsets)

double point_segment_distance(const Vec3& p, const Vec3& a, const Vec3& b, double& t) {
  const Vec3 ab = b - a;
  const double l2 = ab.squaredNorm();
  t = l2 > 0 ? std::clamp((p - a).dot(ab) / l2, 0.0, 1.0) : 0.0;
  return (a + t * ab - p).norm();
}

// A polyline with chords linear per segment, in chunks of segments with bounding spheres, so a
// distance query skips the chunks that cannot hold a closer segment.
class ChordPolyline {
 public:
  ChordPolyline(std::vector<Vec3> pts, std::vector<double> chords) : pts_(std::move(pts)), chords_(std::move(chords)) {
    for (std::size_t a = 0; a + 1 < pts_.size(); a += kChunk) {
      const std::size_t b = std::min(a + kChunk, pts_.size() - 1);  // segments a .. b - 1
      Vec3 c = Vec3::Zero();
      for (std::size_t k = a; k <= b; ++k) c += pts_[k];
      c /= static_cast<double>(b - a + 1);
      double r = 0;
      for (std::size_t k = a; k <= b; ++k) r = std::max(r, (pts_[k] - c).norm());
      chunks_.push_back({a, b, c, r});
    }
  }
  /// Distance from p to the polyline and the chord coordinate of the closest point.
  double distance(const Vec3& p, double& chord_at) const {
    double best = HUGE_VAL;
    auto visit = [&](const Chunk& ch) {
      if ((p - ch.centre).norm() - ch.radius >= best) return;
      for (std::size_t k = ch.first; k < ch.last; ++k) {
        double t = 0;
        const double d = point_segment_distance(p, pts_[k], pts_[k + 1], t);
        if (d < best) {
          best = d;
          chord_at = chords_[k] + t * (chords_[k + 1] - chords_[k]);
        }
      }
    };
    // Successive queries move along the other side: the last closest chunk first.
    visit(chunks_[last_]);
    for (std::size_t i = 0; i < chunks_.size(); ++i) {
      const double before = best;
      if (i != last_) visit(chunks_[i]);
      if (best < before) last_ = i;
    }
    return best;
  }

 private:
  static constexpr std::size_t kChunk = 16;
  struct Chunk {
    std::size_t first, last;  // points first .. last
    Vec3 centre;
    double radius;
  };
  std::vector<Vec3> pts_;
  std::vector<double> chords_;
  std::vector<Chunk> chunks_;
  mutable std::size_t last_ = 0;
};

struct SpanRange {
  double lo, hi;
};

SpanRange span_domain(const BladeModel& m) {
  return {m.surface.first_v(), m.surface.last_v()};
}

// Relative margin below t at which a point counts as too close to the opposite wall (covers the
// polyline's sagitta against the true wall).
constexpr double kCloseMargin = 0.01;
constexpr int kScanSamples = 400;

}  // namespace

namespace {

// Where the suction-side offset I(span, c_s) meets the pressure-side one I(s_p, c_p), by Newton on
// F(c_s, c_p, s_p) = I(span, c_s) - I(s_p, c_p) = 0 with central-difference Jacobian from (cs, cp, span).
// Each new span costs a section (an arc-length table), so the span column is differenced at the first
// iterate only (s_p moves by little; the chord columns stay exact): one new span per iteration.
struct OffsetCrossing {
  double cs = 0, cp = 0, sp = 0, residual = 0;
  bool converged = false;
};

OffsetCrossing offset_crossing(const BladeCoordinates& coords, const ThicknessField& thickness, double span, double cs, double cp) {
  const SpanRange dom = span_domain(coords.model());
  auto I = [&](double s, double c) { return inner_wall_point(coords, thickness, s, c); };
  OffsetCrossing x{cs, cp, span};
  const double h = 1e-6;
  Vec3 F = Vec3::Zero();
  Eigen::Matrix3d J;
  for (int it = 0; it < 40; ++it) {
    F = I(span, x.cs) - I(x.sp, x.cp);
    if (F.norm() < 1e-11) {
      x.converged = true;
      break;
    }
    auto dc = [&](double s, double c) {
      const double a = std::max(c - h, -1.0), b = std::min(c + h, 1.0);
      return Vec3((I(s, b) - I(s, a)) / (b - a));
    };
    J.col(0) = dc(span, x.cs);
    J.col(1) = -dc(x.sp, x.cp);
    if (it == 0) {
      const double sa = std::max(x.sp - h, dom.lo), sb = std::min(x.sp + h, dom.hi);
      J.col(2) = -(I(sb, x.cp) - I(sa, x.cp)) / (sb - sa);
    }
    Vec3 step = J.fullPivLu().solve(-F);
    if (!step.allFinite()) break;
    const double limit = 0.02;  // chord units per step
    const double scale = std::max({std::abs(step[0]), std::abs(step[1]), std::abs(step[2])}) / limit;
    if (scale > 1) step /= scale;
    x.cs = std::clamp(x.cs + step[0], 1e-9, 1.0);
    x.cp = std::clamp(x.cp + step[1], -1.0, -1e-9);
    x.sp = std::clamp(x.sp + step[2], dom.lo, dom.hi);
  }
  x.residual = F.norm();
  return x;
}

}  // namespace

InnerWallSection inner_wall_crease(const BladeCoordinates& coords, const ThicknessField& thickness, double span) {
  const int n = kScanSamples;
  // The scans (polylines, the walk to the first close point, the check for a second crossing) look for
  // a neighbourhood: their points lie on the wall and its offset exactly, at chords within 1e-4 of the
  // section's length of k / n (ChordAccuracy::Near, a seventh of the cost; shifted along the wall, a
  // fraction of the 1 / n sampling); the crease itself is Newton's on exact points.
  auto near_point = [&](double c) { return coords.frame(span, c, ChordAccuracy::Near).point; };
  auto near_inner = [&](double c) { return inner_wall_point(coords, thickness, span, c, ChordAccuracy::Near); };
  std::vector<Vec3> pressure(n + 1), suction(n + 1);
  std::vector<double> pc(n + 1), sc(n + 1);
  for (int k = 0; k <= n; ++k) {
    pc[k] = -static_cast<double>(k) / n;
    sc[k] = static_cast<double>(k) / n;
    pressure[k] = near_point(pc[k]);
    suction[k] = near_point(sc[k]);
  }
  const ChordPolyline pressure_line(std::move(pressure), pc), suction_line(std::move(suction), sc);
  InnerWallSection out;
  out.span = out.pressure_span = span;
  // Walk the suction-side offset from the LE: the first point closer than t to the pressure side. Short
  // of the TE (whose point lies on both sides), the closest approach is kept: offsets that come within
  // the margin of t there may still cross (a wall thicker than the TE's radius: its offset folds there).
  int hit = -1, closest = -1;
  double hit_pressure_chord = -1, closest_ratio = 1, closest_pressure_chord = -1;
  for (int i = 1; i <= n; ++i) {
    const Vec3 q = near_inner(sc[i]);
    double c_at = 0;
    const double d = pressure_line.distance(q, c_at);
    const double ratio = d / thickness.at(span, sc[i]);
    if (ratio < 1 - kCloseMargin) {
      hit = i;
      hit_pressure_chord = c_at;
      break;
    }
    if (i < n && ratio < closest_ratio) {
      closest = i;
      closest_ratio = ratio;
      closest_pressure_chord = c_at;
    }
  }
  auto untrimmed = [&] {
    // No crossing: the inner wall goes round the TE (TE radius >= t). Seam at the TE.
    out.trimmed = false;
    out.suction_chord = 1;
    out.pressure_chord = -1;
    out.crease = inner_wall_point(coords, thickness, span, 1.0);
    return out;
  };
  if (hit < 0 && closest < 0) return untrimmed();
  if (hit == 1)
    throw InnerWallError("inner wall: the wall thickness " + format_number(thickness.at(span, sc[1])) +
                             " mm leaves no core at span " + format_number(span) + " (the blade is thinner than twice the wall "
                             "thickness right behind the leading edge)",
                         span, sc[1]);
  const int at = hit > 0 ? hit : closest;
  const OffsetCrossing x = offset_crossing(coords, thickness, span, sc[at] - 0.5 / n, hit > 0 ? hit_pressure_chord : closest_pressure_chord);
  const bool found = x.converged && x.cs < 1.0 && x.cp > -1.0 && std::abs(x.cs - (sc[at] - 0.5 / n)) <= 4.0 / n;
  if (!found && hit < 0) return untrimmed();  // a close approach that does not cross
  if (!found)
    throw InnerWallError("inner wall: cannot locate where the suction- and pressure-side offsets cross at span " +
                             format_number(span) + " near chord " + format_number(sc[hit]) + " (residual " + format_number(x.residual) +
                             " mm); the wall may be too thick for the trailing-edge region",
                         span, sc[hit]);
  const double cs = x.cs, cp = x.cp, sp = x.sp;
  auto I = [&](double s, double c) { return inner_wall_point(coords, thickness, s, c); };
  // The pressure side up to the crease must keep its distance from the suction side: otherwise the
  // offsets cross a second time (blade thinner than 2t away from the TE).
  for (int k = 1; k <= n && pc[k] > cp + 2.0 / n; ++k) {
    const Vec3 q = near_inner(pc[k]);
    double c_at = 0;
    const double d = suction_line.distance(q, c_at);
    if (d < thickness.at(span, pc[k]) * (1 - kCloseMargin))
      throw InnerWallError("inner wall: the wall thickness exceeds half the blade thickness at span " + format_number(span) +
                               ", pressure-side chord " + format_number(pc[k]) + " before the trailing-edge crossing at chord " +
                               format_number(cp) + " (the offsets cross twice)",
                           span, pc[k]);
  }
  out.trimmed = true;
  out.suction_chord = cs;
  out.pressure_chord = cp;
  out.pressure_span = sp;
  out.crease = I(span, cs);
  return out;
}

namespace {

// ---------------------------------------------------------------------------------------------------
// Exact sections

struct Sample {
  double x = 0;  // position along the section: [0, 1] pressure half (crease -> LE), [1, 2] suction half
  double span = 0, chord = 0;
  Vec3 outer, normal, inner;
};

double smoothstep(double x) { return x * x * (3 - 2 * x); }

// Part of the pressure half (from the crease) over which a section's span blends from the crease's
// pressure span to its own.
constexpr double kBlend = 0.25;

// Exact inner-wall points of one span, sampled along the trimmed section.
class ExactSection {
 public:
  // coords: the calling thread's (sections are built and densified in parallel).
  ExactSection(const BladeCoordinates& coords, const ThicknessField& thickness, double span)
      : thickness_(&thickness), span_(span) {
    info = inner_wall_crease(coords, thickness, span);
    // Steps: at most 1 degree of normal turning and 1/400 of the LE-TE distance along the inner wall,
    // so the curve between samples is resolved far below any fit tolerance.
    const double max_turn = 1.0 * kPi / 180;
    const double max_step = (coords.frame(span, 0.0).point - coords.frame(span, 1.0).point).norm() / 400;
    const int base = 48;
    Sample prev = sample(coords, 0.0);
    samples_.push_back(prev);
    std::vector<Sample> stack;
    for (int k = 1; k <= 2 * base; ++k) {
      stack.assign(1, sample(coords, 2.0 * k / (2 * base)));
      while (!stack.empty()) {
        const Sample& b = stack.back();
        const double angle = std::acos(std::clamp(prev.normal.dot(b.normal), -1.0, 1.0));
        if ((angle > max_turn || (b.inner - prev.inner).norm() > max_step) && b.x - prev.x > 1e-7) {
          stack.push_back(sample(coords, 0.5 * (prev.x + b.x)));
          continue;
        }
        prev = b;
        samples_.push_back(b);
        stack.pop_back();
      }
    }
    // A fold: the offset runs backwards where t exceeds the wall's radius of curvature.
    for (std::size_t i = 0; i + 1 < samples_.size(); ++i) {
      const Sample &a = samples_[i], &b = samples_[i + 1];
      if ((b.inner - a.inner).dot(b.outer - a.outer) <= 0)
        throw InnerWallError("inner wall: the wall thickness " + format_number(thickness.at(a.span, a.chord)) +
                                 " mm exceeds the wall's radius of curvature at span " + format_number(a.span) + ", chord " +
                                 format_number(a.chord) + " (the offset folds; use a thinner wall there)",
                             a.span, a.chord);
    }
    update();
  }

  InnerWallSection info;
  std::vector<Vec3> points;    // crease -> pressure side -> LE -> suction side -> crease
  std::vector<double> params;  // normalised chord length, [0, 1]
  double span() const { return span_; }

  /// Number of samples with parameter in [a, b].
  int count(double a, double b) const {
    return static_cast<int>(std::upper_bound(params.begin(), params.end(), b) -
                            std::lower_bound(params.begin(), params.end(), a));
  }
  /// Halves every sample step that touches [a, b].
  void densify(const BladeCoordinates& coords, double a, double b) {
    std::vector<Sample> out;
    for (std::size_t i = 0; i + 1 < samples_.size(); ++i) {
      out.push_back(samples_[i]);
      if (params[i + 1] >= a && params[i] <= b) out.push_back(sample(coords, 0.5 * (samples_[i].x + samples_[i + 1].x)));
    }
    out.push_back(samples_.back());
    samples_ = std::move(out);
    update();
  }

 private:
  // Foot point of position x: the pressure half blends from the crease's pressure span to the section
  // span with zero slope at both ends (over kBlend of the half), so the section stays smooth. A blended
  // sample blends the surface parameters (span and u) of its chord on the two spans' sections, so it
  // needs no section of its own (an arc-length table per sample); its chord is then the nominal one
  // (exact at both ends of the blend, within the two spans' difference of arc-length shares between).
  Sample sample(const BladeCoordinates& coords, double x) const {
    Sample s;
    s.x = x;
    double w = 0;  // weight of the crease's pressure span
    if (x <= 1) {
      s.chord = info.pressure_chord * (1 - x);
      w = x >= kBlend ? 0.0 : 1 - smoothstep(x / kBlend);
    } else {
      s.chord = info.suction_chord * (x - 1);
    }
    s.span = span_ + (info.pressure_span - span_) * w;
    // The chord decides where along the section the sample lies and, through the thickness, how deep
    // it is. Where the thickness does not vary along the chord, a sample within 1e-4 of the section's
    // length of its nominal place (ChordAccuracy::Near) is as exact a point of the inner wall (only the
    // ends, the crease, must be the crease itself); it saves the arc-length inverse's Newton polish.
    const ChordAccuracy accuracy =
        x == 0 || x == 2 || thickness_->varies_along_chord() ? ChordAccuracy::Exact : ChordAccuracy::Near;
    BladeFrame f;
    if (w == 0) {
      f = coords.frame(span_, s.chord, accuracy);
    } else {
      const double u_own = coords.section(span_).u_at_chordwise(s.chord, accuracy);
      double u_crease = coords.section(info.pressure_span).u_at_chordwise(s.chord, accuracy);
      u_crease -= std::round(u_crease - u_own);  // the same turn of the periodic u (period 1)
      f = coords.frame_at(u_own + (u_crease - u_own) * w, s.span);
    }
    s.outer = f.point;
    s.normal = f.normal;
    s.inner = f.point - thickness_->at(s.span, s.chord) * f.normal;
    return s;
  }
  void update() {
    points.clear();
    for (const Sample& s : samples_) points.push_back(s.inner);
    points.back() = points.front();  // the crease (or the TE offset point), to ~1e-11 mm already
    params.assign(points.size(), 0.0);
    for (std::size_t i = 1; i < points.size(); ++i) params[i] = params[i - 1] + (points[i] - points[i - 1]).norm();
    const double total = params.back();
    require(total > 0, "inner wall: degenerate section at span " + format_number(span_));
    for (double& p : params) p /= total;
    params.back() = 1.0;
  }

  const ThicknessField* thickness_;
  double span_;
  std::vector<Sample> samples_;
};

// ---------------------------------------------------------------------------------------------------
// Fitting

struct SectionFit {
  BSplineCurve<3> curve;
  std::vector<double> interval_error;  // max residual per distinct knot interval
};

// Distinct knot intervals of a clamped knot vector: [breaks[k], breaks[k + 1]].
std::vector<double> breaks_of(const std::vector<double>& U) {
  std::vector<double> b;
  for (double u : U)
    if (b.empty() || u > b.back()) b.push_back(u);
  return b;
}

SectionFit fit_section(const ExactSection& s, const std::vector<double>& knots) {
  SectionFit f;
  f.curve = fit_least_squares<3>(s.points, s.params, 3, knots);
  const std::vector<double> br = breaks_of(knots);
  f.interval_error.assign(br.size() - 1, 0.0);
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    const double e = (f.curve.point(s.params[i]) - s.points[i]).norm();
    std::size_t k = static_cast<std::size_t>(std::upper_bound(br.begin(), br.end(), s.params[i]) - br.begin());
    k = std::clamp<std::size_t>(k, 1, br.size() - 1) - 1;
    f.interval_error[k] = std::max(f.interval_error[k], e);
  }
  return f;
}

// One BladeCoordinates per worker thread (each caches its own sections); sections of different spans
// are independent, so they are built, densified, fitted and checked in parallel.
class Workers {
 public:
  explicit Workers(const BladeModel& model) {
    for (int w = 0; w < parallel_workers(); ++w) coords_.push_back(std::make_unique<BladeCoordinates>(model));
  }
  const BladeCoordinates& first() const { return *coords_.front(); }
  /// f(i, coords) for i in [0, n); the error of the lowest failing i is rethrown (as in a serial loop).
  template <class F>
  void run(std::size_t n, F&& f) const {
    parallel_for(static_cast<int>(n), static_cast<int>(coords_.size()),
                 [&](int i, int w) { f(static_cast<std::size_t>(i), *coords_[static_cast<std::size_t>(w)]); });
  }

 private:
  std::vector<std::unique_ptr<BladeCoordinates>> coords_;
};

// Fits every section on one shared knot vector, refining it where any section exceeds tol / 2.
std::vector<BSplineCurve<3>> fit_sections(const Workers& workers, std::vector<ExactSection>& sections,
                                          std::vector<double>& knots, double tol) {
  for (int round = 0; round < 30; ++round) {
    const std::vector<double> b0 = breaks_of(knots);
    std::vector<SectionFit> fits(sections.size());
    workers.run(sections.size(), [&](std::size_t i, const BladeCoordinates& coords) {
      // Schoenberg-Whitney with margin: every section needs a few samples in every knot interval.
      ExactSection& sec = sections[i];
      for (std::size_t k = 0; k + 1 < b0.size(); ++k)
        for (int guard = 0; guard < 8 && sec.count(b0[k], b0[k + 1]) < 4; ++guard)
          sec.densify(coords, b0[k], b0[k + 1]);
      fits[i] = fit_section(sec, knots);
    });
    const std::vector<double>& br = b0;
    std::vector<double> insert;
    for (std::size_t k = 0; k + 1 < br.size(); ++k) {
      double e = 0;
      for (const auto& f : fits) e = std::max(e, f.interval_error[k]);
      if (e <= 0.5 * tol) continue;
      const double m = 0.5 * (br[k] + br[k + 1]);
      insert.push_back(m);
    }
    if (insert.empty()) {
      std::vector<BSplineCurve<3>> out;
      for (auto& f : fits) out.push_back(std::move(f.curve));
      return out;
    }
    knots.insert(knots.end(), insert.begin(), insert.end());
    std::sort(knots.begin(), knots.end());
  }
  throw AlgorithmFailure("inner wall: the section fit does not reach the tolerance " + format_number(tol) +
                         " mm after 30 refinements");
}

// Newton foot point of q on the surface from (u, v): the fitting error at an exact point.
double surface_distance(const BSplineSurface<3>& S, const Vec3& q, double u, double v) {
  for (int it = 0; it < 12; ++it) {
    Vec3 d[9];
    S.derivatives(u, v, 2, d);  // d[k * 3 + l] = S^(k, l)
    const Vec3 r = d[0] - q;
    const Vec3 &Su = d[3], &Sv = d[1], &Suu = d[6], &Suv = d[4], &Svv = d[2];
    Eigen::Matrix2d H;
    H << Su.dot(Su) + r.dot(Suu), Su.dot(Sv) + r.dot(Suv), Su.dot(Sv) + r.dot(Suv), Sv.dot(Sv) + r.dot(Svv);
    const Eigen::Vector2d g(r.dot(Su), r.dot(Sv));
    Eigen::Vector2d step = H.fullPivLu().solve(-g);
    if (!step.allFinite()) break;
    u = std::clamp(u + step.x(), S.first_u(), S.last_u());
    v = std::clamp(v + step.y(), S.first_v(), S.last_v());
    if (step.norm() < 1e-14) break;
  }
  return (S.point(u, v) - q).norm();
}

// The clamped, closed (first pole == last pole) cubic surface in u as a u-periodic surface with a knot
// of full multiplicity p at the seam: unwrapped poles [P_{n-p+1} .. P_{n-1}, P_0 .. P_{n-1}, P_0]
// (the seam point is pole p - 1; see the periodic storage in bspline_curve.hpp).
BSplineSurface<3> to_periodic_u(const BSplineSurface<3>& S) {
  const int p = S.degree_u(), N = S.num_poles_u() - 1;  // poles 0..N, pole N == pole 0
  const int nv = S.num_poles_v();
  const std::vector<double>& U = S.knots_u();
  // One period of flat knots: the seam 0 with multiplicity p, then the interior knots.
  std::vector<double> period(static_cast<std::size_t>(p), U[static_cast<std::size_t>(p)]);
  for (int i = p + 1; i < N + 1; ++i) period.push_back(U[static_cast<std::size_t>(i)]);
  const int n = static_cast<int>(period.size());  // == N distinct poles
  require(n == N, "inner wall: periodic conversion: knot count mismatch");
  const std::vector<double> Uper = unwrap_periodic_knots(p, period, U[static_cast<std::size_t>(N + p)] - U[static_cast<std::size_t>(p)]);
  BSplineSurface<3>::HPoles h(4, static_cast<Eigen::Index>((n + p) * nv));
  for (int i = 0; i < n + p; ++i) {
    const int src = ((i - (p - 1)) % n + n) % n;
    for (int j = 0; j < nv; ++j) h.col(i * nv + j) = S.homogeneous_pole(src, j);
  }
  return BSplineSurface<3>::from_homogeneous(p, S.degree_v(), Uper, S.knots_v(), n + p, nv, h, true, false);
}

}  // namespace

std::pair<double, double> inner_wall_span_range(const BladeModel& model, const InnerWallOptions& options) {
  const SpanRange dom = span_domain(model);
  const double ob = std::min(0.0 - dom.lo, dom.hi - 1.0);
  const double lo = std::isnan(options.span_min) ? dom.lo + 0.2 * ob : options.span_min;
  const double hi = std::isnan(options.span_max) ? dom.hi - 0.2 * ob : options.span_max;
  require(lo >= dom.lo && hi <= dom.hi && hi > lo, "inner wall: span range [" + format_number(lo) + ", " + format_number(hi) +
                                                       "] must lie inside the blade's [" + format_number(dom.lo) + ", " +
                                                       format_number(dom.hi) + "]");
  return {lo, hi};
}

InnerWall build_inner_wall(const BladeModel& model, const ThicknessField& thickness, const InnerWallOptions& options) {
  require(options.tolerance > 0 && std::isfinite(options.tolerance),
          "inner wall: tolerance must be > 0 mm, got " + format_number(options.tolerance));
  require(thickness.max_value() > 0, "inner wall: the thickness field is empty");
  const Workers workers(model);
  const auto [lo, hi] = inner_wall_span_range(model, options);
  const double tol = options.tolerance;

  std::vector<double> spans;
  const int initial = 9;
  for (int k = 0; k < initial; ++k) spans.push_back(lo + (hi - lo) * k / (initial - 1));
  std::vector<ExactSection> sections;
  {
    std::vector<std::optional<ExactSection>> built(spans.size());
    workers.run(spans.size(), [&](std::size_t k, const BladeCoordinates& c) { built[k].emplace(c, thickness, spans[k]); });
    for (auto& b : built) sections.push_back(std::move(*b));
  }

  // Initial knots: averaged over the middle section's parameters, about one pole per four samples.
  const ExactSection& mid = sections[sections.size() / 2];
  const int npoles = std::clamp(static_cast<int>(mid.params.size()) / 4, 8, 60);
  std::vector<double> knots = approximation_knots(mid.params, 3, npoles);

  InnerWall wall;
  for (int round = 0; round < 12; ++round) {
    const std::vector<BSplineCurve<3>> curves = fit_sections(workers, sections, knots, tol);
    SkinOptions so;
    so.degree_v = 3;
    so.v_params = spans;
    const BSplineSurface<3> S = skin(curves, so).surface;
    // Verify midway between fitted spans; bisect where the exact section is farther than tol.
    const std::size_t gaps = spans.size() - 1;
    std::vector<std::optional<ExactSection>> midway(gaps);
    std::vector<double> error(gaps, 0.0);
    std::vector<int> checked_at(gaps, 0);
    workers.run(gaps, [&](std::size_t k, const BladeCoordinates& c) {
      const double sm = 0.5 * (spans[k] + spans[k + 1]);
      const ExactSection& e = midway[k].emplace(c, thickness, sm);
      for (std::size_t i = 0; i < e.points.size(); i += 2) {
        error[k] = std::max(error[k], surface_distance(S, e.points[i], e.params[i], sm));
        ++checked_at[k];
      }
    });
    std::vector<double> new_spans;
    std::vector<ExactSection> new_sections;
    double worst = 0;
    int checked = 0;
    for (std::size_t k = 0; k < gaps; ++k) {
      worst = std::max(worst, error[k]);
      checked += checked_at[k];
      if (error[k] > 0.5 * tol) {
        new_spans.push_back(midway[k]->span());
        new_sections.push_back(std::move(*midway[k]));
      }
    }
    if (new_spans.empty()) {
      wall.surface = to_periodic_u(S);
      wall.max_fit_error = worst;
      wall.checked_points = checked;
      break;
    }
    if (spans.size() + new_spans.size() > 400)
      throw AlgorithmFailure("inner wall: more than 400 spans needed to reach the tolerance " + format_number(tol) + " mm");
    for (std::size_t k = 0; k < new_spans.size(); ++k) {
      const auto pos = std::upper_bound(spans.begin(), spans.end(), new_spans[k]) - spans.begin();
      spans.insert(spans.begin() + pos, new_spans[k]);
      sections.insert(sections.begin() + pos, std::move(new_sections[k]));
    }
    if (round == 11) throw AlgorithmFailure("inner wall: span refinement does not converge");
  }
  for (const ExactSection& s : sections) {
    wall.sections.push_back(s.info);
    wall.min_suction_chord = std::min(wall.min_suction_chord, s.info.suction_chord);
    wall.max_pressure_chord = std::max(wall.max_pressure_chord, s.info.pressure_chord);
  }
  return wall;
}

}  // namespace cg::blade
