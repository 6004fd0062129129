#pragma once
// The meridional (S2M) net of a blade row: hub and casing contours, streamlines between them and
// quasi-orthogonal stations (among them the leading- and trailing-edge lines), all in the (x, r) plane.
//
// Axis convention (used by the whole blade model): x is the engine axis (axial, mm), r the radius (mm).
// A point (x, r) at circumferential angle theta is the 3D point (x, r cos(theta), r sin(theta)); revolving
// a meridional curve about the x axis gives a surface of revolution.
//
// On each streamline the meridional arc length m (dm = sqrt(dx^2 + dr^2)) and the conformal coordinate
// m' = integral dm / r are tabulated by Gauss-Legendre quadrature; the map (m', theta) -> stream surface is
// conformal, so angles drawn in (m', theta) are true 3D angles.
#include <Eigen/Core>
#include <optional>
#include <vector>

#include "src/blade/curve_integral.hpp"
#include "src/blade/span_spline.hpp"
#include "src/core/bspline_curve.hpp"

namespace cg::blade {

/// Points of a contour in the (x, r) plane, mm.
using MeridionalPolyline = std::vector<Eigen::Vector2d>;

/// Input of the net. Contours run upstream -> downstream; each is interpolated by a cubic (or lower, for
/// fewer points) NURBS through its points with chord-length parameters (2 points -> straight line).
struct MeridionalNetDefinition {
  MeridionalPolyline hub;     // span 0
  MeridionalPolyline casing;  // span 1
  /// Interior streamlines given explicitly, each with its span fraction in (0, 1), strictly increasing.
  std::vector<MeridionalPolyline> streamlines;
  std::vector<double> streamline_spans;
  /// Span fractions in (0, 1) at which further streamlines are interpolated between the given ones.
  std::vector<double> interpolated_spans;
  /// Quasi-orthogonal lines from hub to casing (>= 2 points; 2 points = straight line). Each must cut every
  /// streamline exactly once; a line may start/end slightly outside the flow path (it is not extended).
  MeridionalPolyline leading_edge;   // optional (empty = none); required by meridional blades
  MeridionalPolyline trailing_edge;  // optional
  std::vector<MeridionalPolyline> stations;
  /// Points per streamline used when blending streamlines (interpolated spans, over-build), [16, 100000].
  int samples = 129;
};

/// One streamline: a curve C(u) = (x(u), r(u)) with tabulated m(u) and m'(u).
class Streamline {
 public:
  Streamline() = default;
  /// Tabulates m and m'. Throws InvalidGeometry when r <= 0 anywhere on the curve.
  Streamline(BSplineCurve<2> curve, double span);

  const BSplineCurve<2>& curve() const { return curve_; }
  double span() const { return span_; }
  double first_param() const { return curve_.first_param(); }
  double last_param() const { return curve_.last_param(); }
  Eigen::Vector2d point(double u) const { return curve_.point(u); }

  /// Meridional arc length from the curve start to u, mm.
  double meridional_length(double u) const;
  double total_length() const { return m_.total(); }
  /// m'(u) = integral_{u0}^{u} |C'| / r du (dimensionless).
  double m_prime(double u) const;
  double total_m_prime() const { return mp_.total(); }
  /// Inverse of m_prime (Newton with bisection safeguard). Throws InvalidGeometry outside [0, total].
  double param_at_m_prime(double m_prime) const;
  /// Inverse of meridional_length.
  double param_at_length(double m) const;

 private:
  BSplineCurve<2> curve_;
  double span_ = 0;
  detail::CurveIntegral m_, mp_;
};

/// Where a quasi-orthogonal cuts one streamline.
struct StationCut {
  double streamline_param = 0;  // u on the streamline
  double station_param = 0;     // parameter on the quasi-orthogonal curve
  Eigen::Vector2d point = Eigen::Vector2d::Zero();
};

/// A quasi-orthogonal station: its curve and its cuts with every streamline of the net (hub first).
struct QuasiOrthogonal {
  BSplineCurve<2> curve;
  std::vector<StationCut> cuts;
};

/// The validated net. Value type (copyable).
class MeridionalNet {
 public:
  /// Builds and validates: r > 0 on every contour, neighbouring streamlines do not touch or cross (no
  /// curve-curve intersection, src/algo/intersect_curves, and the same side as casing vs hub at mid-length),
  /// every station cuts every streamline exactly once.
  /// Throws InvalidGeometry naming the offending contour.
  explicit MeridionalNet(const MeridionalNetDefinition& def);

  /// All streamlines, hub first, casing last, span strictly increasing.
  const std::vector<Streamline>& streamlines() const { return streamlines_; }
  const Streamline& hub() const { return streamlines_.front(); }
  const Streamline& casing() const { return streamlines_.back(); }

  /// Streamline at any span fraction: points at equal normalised meridional length on the defining
  /// streamlines (hub, explicit streamlines, casing) are blended by the natural cubic spline over span
  /// through them (span_spline.hpp: linear for hub and casing alone; smooth in span, so blade sections
  /// between streamlines vary smoothly too; linear continuation outside [0, 1], used for the
  /// over-build) and interpolated. Returns the stored streamline when span matches one.
  Streamline streamline_at(double span) const;

  const std::optional<QuasiOrthogonal>& leading_edge() const { return leading_edge_; }
  const std::optional<QuasiOrthogonal>& trailing_edge() const { return trailing_edge_; }
  const std::vector<QuasiOrthogonal>& stations() const { return stations_; }

 private:
  std::vector<Streamline> streamlines_;
  std::optional<QuasiOrthogonal> leading_edge_, trailing_edge_;
  std::vector<QuasiOrthogonal> stations_;
  int samples_ = 129;
  // Defining streamlines: their spans and their points at equal normalised meridional length.
  detail::SpanSpline defining_;
  std::vector<std::vector<Eigen::Vector2d>> defining_points_;
};

/// Curve through the points in order (cubic, or degree n-1 for n < 4 points; chord-length parameters).
/// Throws InvalidGeometry for < 2 points or coincident consecutive points; `what` names the contour.
BSplineCurve<2> meridional_curve(const MeridionalPolyline& points, const char* what);

/// The unique cut of `station` with `streamline` (src/algo/intersect_curves, tolerance 1e-9 mm, so a
/// station ending exactly on a contour counts). found=false when there is no cut; throws InvalidGeometry
/// when there is more than one or the curves overlap.
struct StationCutResult {
  bool found = false;
  StationCut cut;
};
StationCutResult cut_station(const BSplineCurve<2>& station, const Streamline& streamline);

}  // namespace cg::blade
