#include "src/grid/wall_nodes.hpp"

#include <algorithm>
#include <cmath>

#include "src/analyze/frenet.hpp"
#include "src/core/constants.hpp"
#include "src/grid/distribution.hpp"

namespace cg::grid {

WallArc::WallArc(const blade::SectionProfile& section)
    : section_(&section), table_(section.curve), suction_(section.suction_length()), pressure_(section.pressure_length()) {
  le_offset_ = table_.length_to(wrap(section.le_param));
}

double WallArc::wrap(double u) const {
  const double a = section_->curve.first_param(), T = section_->curve.period();
  return a + std::fmod(std::fmod(u - a, T) + T, T);
}

double WallArc::position(double u) const {
  const double P = perimeter();
  const double s = table_.length_to(wrap(u)) - le_offset_;
  return std::fmod(std::fmod(s, P) + P, P);
}

std::vector<double> WallArc::params(const std::vector<double>& s) const {
  const double P = perimeter(), T = section_->curve.period();
  std::vector<double> c(s.size());
  std::vector<double> turns(s.size());
  for (std::size_t k = 0; k < s.size(); ++k) {
    const double n = std::floor(s[k] / P);
    const double r = s[k] - n * P;  // [0, P)
    turns[k] = n;
    c[k] = r <= suction_ ? r / suction_ : -1.0 + (r - suction_) / pressure_;
  }
  std::vector<double> u = section_->params_at_chordwise(c);
  for (std::size_t k = 0; k < s.size(); ++k) {
    // The pressure side runs from the TE to le_param + T; c = 0 maps to le_param itself.
    if (c[k] < 0 && u[k] < section_->te_param) u[k] += T;
    u[k] += turns[k] * T;
  }
  return u;
}

std::vector<double> clustered_wall_positions(const blade::SectionProfile& section, const WallArc& arc, int cells,
                                             double clustering) {
  const double P = arc.perimeter();
  const int per_cell = 16, n = cells * per_cell;
  std::vector<double> s(static_cast<std::size_t>(n) + 1);
  for (int k = 0; k <= n; ++k) s[static_cast<std::size_t>(k)] = P * k / n;
  const std::vector<double> u = arc.params(s);
  std::vector<double> raw(static_cast<std::size_t>(n));
  for (int k = 0; k < n; ++k)
    raw[static_cast<std::size_t>(k)] =
        1.0 + clustering * std::abs(signed_curvature(section.curve, u[static_cast<std::size_t>(k)])) * P / (2 * kPi);
  // Smoothed over 1.5 mean cells: the curvature of an interpolated profile jumps where an edge circle
  // meets a flank; the cell sizes should not.
  std::vector<double> density = smooth_periodic(raw, 1.5 * per_cell);
  density.push_back(density.front());
  return equidistribute(density, cells, P);
}

}  // namespace cg::grid
