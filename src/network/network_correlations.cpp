#include "src/network/network_correlations.hpp"

#include <algorithm>
#include <cmath>

namespace cg::network {

double air_cp(double t) {
  t = std::clamp(t, 273.0, 1800.0);
  // Ideal-gas air (Cengel & Boles, Thermodynamics, table A-2c, 273-1800 K): molar cp in kJ/(kmol K)
  // = 28.11 + 0.1967e-2 T + 0.4802e-5 T^2 - 1.966e-9 T^3, molar mass 28.97 kg/kmol.
  const double molar = 28.11 + t * (0.1967e-2 + t * (0.4802e-5 - t * 1.966e-9));
  return molar / 28.97 * 1000;
}

double air_viscosity(double t) { return 1.716e-5 * std::pow(t / 273.15, 1.5) * (273.15 + 110.4) / (t + 110.4); }

Turbulation turbulation(const features::TurbulatorDefinition& t, double dh, double aspect, double length) {
  Turbulation r;
  r.height = t.height;
  r.pitch = t.pitch;
  r.e_dh = t.height / dh;
  r.p_e = t.pitch / t.height;
  r.angle_deg = t.angle_deg;
  r.walls = t.walls == features::TurbulatorWalls::Both ? "both" : t.walls == features::TurbulatorWalls::Suction ? "suction" : "pressure";
  const int walls = t.walls == features::TurbulatorWalls::Both ? 2 : 1;
  r.count = walls * static_cast<int>(std::floor(length / t.pitch));
  // Han: R(e+) = sqrt(2 / f_r) + 2.5 ln(2 e/Dh * 2W/(W+H)) + 2.5, fully rough R from the rib angle and
  // P/e; the ribbed walls' share of the perimeter W / (2 (W + H)) per ribbed wall.
  const double w_h = std::isnan(aspect) ? 1.0 : aspect;
  const double a = t.angle_deg / 90;
  const double big_r = (12.31 - 27.07 * a + 17.86 * a * a) * std::pow(r.p_e / 10, 0.35);
  const double g = big_r - 2.5 * std::log(2 * r.e_dh * 2 * w_h / (w_h + 1)) - 2.5;
  r.friction_factor = g > 0 ? 2 / (g * g) : 0.5;
  r.ribbed_fraction = walls * w_h / (2 * (w_h + 1));
  return r;
}

double equivalent_roughness(const Turbulation& t, double dh) {
  const double f_smooth = 0.046 * std::pow(2e4, -0.2);  // Fanning, smooth channel at Re 2e4
  const double f = t.ribbed_fraction * t.friction_factor + (1 - t.ribbed_fraction) * f_smooth;
  const double darcy = 4 * f;
  // Fully rough Colebrook: 1 / sqrt(f_D) = -2 log10(k_s / (3.7 D)).
  return 3.7 * dh * std::pow(10.0, -1 / (2 * std::sqrt(darcy)));
}

PinBank pin_bank(const features::PinFinDefinition& p, int pins) {
  PinBank b;
  b.diameter = p.diameter;
  b.s_d = p.spanwise_pitch / p.diameter;
  b.x_d = p.streamwise_pitch / p.diameter;
  b.rows = p.rows;
  b.pins = pins;
  b.loss_per_row = pin_row_loss(b.re_d);
  return b;
}

double pin_row_loss(double re_d) { return 4 * 0.317 * std::pow(std::clamp(re_d, 1e3, 1e5), -0.132); }

}  // namespace cg::network
