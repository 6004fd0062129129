#include "features/film/hole_shape.hpp"

#include <algorithm>
#include <cmath>

#include "src/core/constants.hpp"
#include "src/core/error.hpp"
#include "src/core/format.hpp"

namespace cg::features {
namespace {
double tan_deg(double a) { return std::tan(a * kPi / 180); }
}  // namespace

double FanSection::area() const {
  const double h = y1 - y0;
  return 2 * w * h + 2 * rho * h + 4 * w * rho + kPi * rho * rho;
}

FanProfile::FanProfile(const HoleShape& shape, double diffuser_length)
    : r_(0.5 * shape.diameter),
      ld_(diffuser_length),
      tl_(tan_deg(shape.fan.lateral_angle_deg)),
      tf_(tan_deg(shape.fan.forward_angle_deg)),
      re_(shape.fan.edge_radius_d * shape.diameter) {
  require(shape.kind == HoleKind::FanShaped, "FanProfile: not a fan-shaped hole");
  require(ld_ > 0, "fan-shaped hole: the diffuser length must be > 0");
  require(re_ > 0 && re_ <= max_edge_radius(shape, ld_) * (1 + 1e-12),
          "fan-shaped hole: edge radius must be in (0, " + format_limit(max_edge_radius(shape, ld_), Allowed::below) + "] mm");
}

FanSection FanProfile::at(double t) const {
  FanSection s;
  s.rho = r_ + (t / ld_) * (re_ - r_);
  s.w = r_ + t * tl_ - s.rho;
  s.y0 = -r_ + s.rho;
  s.y1 = r_ + t * tf_ - s.rho;
  return s;
}

std::array<double, 3> FanProfile::area_polynomial() const {
  // w = a t, h = y1 - y0 = b t, rho = r + c t with a = tl - c, b = tf - 2c, c = (re - r) / ld:
  // area = 2 w h + 2 rho h + 4 w rho + pi rho^2.
  const double c = (re_ - r_) / ld_, a = tl_ - c, b = tf_ - 2 * c;
  return {kPi * r_ * r_, 2 * r_ * b + 4 * a * r_ + 2 * kPi * r_ * c,
          2 * a * b + 2 * c * b + 4 * a * c + kPi * c * c};
}

double max_edge_radius(const HoleShape& shape, double diffuser_length) {
  const double r = 0.5 * shape.diameter;
  return r + diffuser_length * std::min(tan_deg(shape.fan.lateral_angle_deg), 0.5 * tan_deg(shape.fan.forward_angle_deg));
}

double area_ratio_station(const HoleShape& shape, double diffuser_length, double inclination_deg) {
  return diffuser_length - shape.diameter / (2 * tan_deg(inclination_deg));
}

double published_area_ratio(const HoleShape& shape, double inclination_deg) {
  const double D = shape.diameter, ls = area_ratio_station(shape, shape.fan.diffuser_length_d * D, inclination_deg);
  return 1 + (4 / kPi) * ((2 * ls * tan_deg(shape.fan.lateral_angle_deg) / D + 1) *
                              (ls * tan_deg(shape.fan.forward_angle_deg) / D + 1) -
                          1);
}

}  // namespace cg::features
