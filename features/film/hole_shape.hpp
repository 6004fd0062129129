#pragma once
// Film-cooling hole shapes and their exact cross-sections.
//
// A hole is described in its own frame: the axis direction d points into the wall (from the outside
// towards the chamber), e_f ("forward") is the unit vector normal to d towards the downstream surface
// (the side the laidback wall expands to), e_l = d x e_f the lateral direction. The exit point E is
// where the axis meets the outer surface.
//
//  - Cylindrical: a circular cylinder of diameter D along the axis.
//  - Laidback fan-shaped (the 7-7-7 family, Schroeder & Thole, GT2014-25992): a metering cylinder of
//    diameter D, then towards the exit a diffuser whose two lateral walls open by the lateral angle phi
//    each and whose downstream wall lays back by the forward angle psi. The diffuser starts at its
//    length L_d (along the axis) inside E. At a distance t from the diffuser start its cross-section
//    (normal to d) is the rounded rectangle
//        x in [-(r + t tan phi), r + t tan phi],  y in [-r, r + t tan psi],  corner radius rho(t),
//    (x along e_l, y along e_f, r = D / 2) with rho(t) = r + (t / L_d)(r_e - r), r_e the edge radius at
//    the exit (t = L_d). With r_e = r the cross-section is the Minkowski sum of the metering disc and a
//    rectangle, the construction behind the published area-ratio formula
//        AR = 1 + (4 / pi) [(2 L* tan(phi) / D + 1)(L* tan(psi) / D + 1) - 1],  L* = L_d - D / (2 tan alpha)
//    (../shared/notes/kernel-references.md): the area at distance L* from the diffuser start over the
//    metering area. Every boundary quantity (half widths, corner centres, radius) is linear in t, so the
//    diffuser is a ruled solid: its walls are planes (the straight sides) and ruled patches between
//    the metering circle's quarter arcs and the exit's corner arcs.
// The 7-7-7 preset: alpha 30 deg, phi = psi = 7 deg, L/D 6 (metering 2.5 D, diffuser 3.5 D), P/D 6,
// r_e = r; it gives AR = 2.50.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <string>

namespace cg::features {

enum class HoleKind { Cylindrical, FanShaped };

/// The diffuser of a laidback fan-shaped hole. Exactly one of diffuser_length_d and metering_length_d
/// is > 0: the other follows from the local wall (the hole's length between the inner and the outer
/// wall along its axis).
struct FanDiffuser {
  double lateral_angle_deg = 7;  ///< phi, expansion of each lateral wall, [0, 20]
  double forward_angle_deg = 7;  ///< psi, laidback expansion of the downstream wall, [0, 20]
  double diffuser_length_d = 3.5;  ///< L_d / D along the axis from the diffuser start to the exit point
  double metering_length_d = 0;    ///< L_m / D along the axis from the inlet (inner wall) to the diffuser start
  double edge_radius_d = 0.5;      ///< r_e / D, corner radius of the cross-section at the exit point
};

struct HoleShape {
  HoleKind kind = HoleKind::Cylindrical;
  double diameter = 0.5;  ///< D, mm (metering diameter)
  FanDiffuser fan;        ///< FanShaped only
};

/// The public 7-7-7 laidback fan-shaped hole of diameter D (diffuser 3.5 D, edge radius D / 2). Inline:
/// the config parser (no OCCT) uses it.
inline HoleShape preset_777(double diameter) {
  HoleShape s;
  s.kind = HoleKind::FanShaped;
  s.diameter = diameter;
  s.fan = FanDiffuser{7, 7, 3.5, 0, 0.5};
  return s;
}

/// The diffuser cross-section at distance t from the diffuser start (see the header comment): corner
/// centres at (+-w, y0) and (+-w, y1), corner radius rho. Everything is linear in t.
struct FanSection {
  double w = 0, y0 = 0, y1 = 0, rho = 0;
  double area() const;                       ///< mm^2
  double half_width() const { return w + rho; }
  double front() const { return y1 + rho; }  ///< largest y
};

/// Fan-shaped cross-section geometry for a given diffuser length L_d (mm).
class FanProfile {
 public:
  FanProfile(const HoleShape& shape, double diffuser_length);
  FanSection at(double t) const;
  /// Area of the cross-section at t as the polynomial a0 + a1 t + a2 t^2 (exact).
  std::array<double, 3> area_polynomial() const;
  double radius() const { return r_; }
  double diffuser_length() const { return ld_; }
  double tan_lateral() const { return tl_; }
  double tan_forward() const { return tf_; }
  double edge_radius() const { return re_; }

 private:
  double r_, ld_, tl_, tf_, re_;
};

/// Largest edge radius the diffuser allows (its straight sides must not have negative length), mm.
double max_edge_radius(const HoleShape& shape, double diffuser_length);

/// The exit-to-metering area ratio of the published formula for inclination alpha (see the header).
double published_area_ratio(const HoleShape& shape, double inclination_deg);

/// The distance L* = L_d - D / (2 tan alpha) of the formula, mm.
double area_ratio_station(const HoleShape& shape, double diffuser_length, double inclination_deg);

/// The frame of a hole: axis d (into the wall), forward e_f, lateral e_l = d x e_f.
struct HoleFrame {
  Eigen::Vector3d exit = Eigen::Vector3d::Zero();  ///< where the axis meets the outer surface
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();
  Eigen::Vector3d forward = Eigen::Vector3d::UnitX();
  Eigen::Vector3d lateral() const { return axis.cross(forward); }
};

}  // namespace cg::features
