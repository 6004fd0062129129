#include "src/ortho/monte_carlo.hpp"

#include <cmath>
#include <string>

#include "src/core/error.hpp"

namespace cg::ortho {

template <int Dim>
MonteCarloContinuation<Dim>::MonteCarloContinuation(const ContinuationNet<Dim>& start, const PerformanceMap& eta,
                                                    const MonteCarloOptions& options)
    : net_(start), sampler_(start.curve, eta, options.panels, options.nodes_per_panel), opt_(options), rng_(options.seed) {
  require(opt_.weight_scale > 0, "Monte Carlo: weight_scale (lambda) must be > 0");
  require(opt_.max_cycles >= 1 && opt_.attempts_per_set >= 1 && opt_.max_attempts_per_visit >= 1,
          "Monte Carlo: cycles and attempt counts must be >= 1");
  require(opt_.initial_pace > 0 && opt_.accuracy > 0 && opt_.accuracy < opt_.initial_pace,
          "Monte Carlo: need 0 < accuracy < initial_pace");
  require(opt_.pace_reduction > 0 && opt_.pace_reduction < 1, "Monte Carlo: pace_reduction must be in (0, 1)");
  net_.surface();  // validates thread 1
  size_ = start.curve.homogeneous_poles().colwise().norm().maxCoeff();
  sampler_.edge_vectors(net_.thread1, V_);
  score_ = sampler_.score(V_);
  report_.start_score = report_.score = score_;
}

template <int Dim>
double MonteCarloContinuation<Dim>::uniform() {
  return static_cast<double>(rng_() >> 11) * 0x1.0p-53;
}

template <int Dim>
typename MonteCarloContinuation<Dim>::HPoint MonteCarloContinuation<Dim>::random_vector(double pace) {
  HPoint r = HPoint::Zero();
  if (opt_.perturbation == Perturbation::WeightOnly) {
    r[Dim] = pace * (2 * uniform() - 1);
    return r;
  }
  do {  // uniform in the unit ball by rejection from the cube
    for (int d = 0; d <= Dim; ++d) r[d] = 2 * uniform() - 1;
  } while (r.squaredNorm() > 1.0);
  r *= pace;
  if (opt_.perturbation == Perturbation::ScaledWeight) r[Dim] *= opt_.weight_scale;
  return r;
}

template <int Dim>
void MonteCarloContinuation<Dim>::visit(int i) {
  double pace = opt_.initial_pace * size_;
  int attempts = 0;
  while (pace >= opt_.accuracy * size_ && attempts < opt_.max_attempts_per_visit) {
    bool improved = false;
    for (int a = 0; a < opt_.attempts_per_set && attempts < opt_.max_attempts_per_visit; ++a) {
      ++attempts;
      ++report_.attempts;
      const HPoint r = random_vector(pace);
      if (!(net_.thread1(Dim, i) + r[Dim] > 0)) continue;  // weights stay positive
      trial_ = V_;
      sampler_.add_point_change(i, r, trial_);
      const double s = sampler_.score(trial_);
      if (s < score_) {  // "if the score increases, the replacement is cancelled"
        net_.thread1.col(i) += r;
        V_.swap(trial_);
        score_ = s;
        improved = true;
        ++report_.accepted;
      }
    }
    if (!improved) pace *= opt_.pace_reduction;
  }
}

template <int Dim>
std::vector<int> MonteCarloContinuation<Dim>::sweep_order(int c) const {
  // "Lop-sided": always from the left; zig-zag: every second cycle from the right (end of Sec. 5).
  const int m = net_.curve.degree();
  const bool reverse = opt_.sweep == SweepOrder::ZigZag && c % 2 == 1;
  std::vector<int> order;
  for (int j = 0; j <= m; ++j) order.push_back(reverse ? m - j : j);
  return order;
}

template <int Dim>
void MonteCarloContinuation<Dim>::cycle() {
  if (done_) return;
  for (int i : sweep_order(report_.cycles)) visit(i);
  ++report_.cycles;
  // Recompute from scratch once per cycle (the incremental updates accumulate rounding).
  sampler_.edge_vectors(net_.thread1, V_);
  score_ = sampler_.score(V_);
  report_.score = score_;
  report_.cycle_scores.push_back(score_);
  report_.cycle_attempts.push_back(report_.attempts);
  if (report_.cycles >= opt_.max_cycles || score_ <= opt_.target_score) done_ = true;
}

template <int Dim>
void MonteCarloContinuation<Dim>::run() {
  while (!done_) cycle();
}

template class MonteCarloContinuation<2>;
template class MonteCarloContinuation<3>;

}  // namespace cg::ortho
