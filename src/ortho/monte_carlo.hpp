#pragma once
// The Monte Carlo method of Lang & Schroecker 1999, Sec. 5: near-orthogonal (or any target angle)
// continuations without degree elevation. Thread 0 (the curve) stays fixed; the homogeneous points of
// thread 1 are perturbed one at a time by random vectors no longer than the current "pace"; a change is
// kept when it lowers the score (18) (here the squared deviation from the performance map, see
// EdgeAngleSampler::score). A visit of one point makes sets of attempts; when a whole set fails the
// pace is reduced, and the visit ends when the pace falls below the accuracy limit. A cycle visits every
// point of thread 1, left to right or in the "zig-zag" order (alternating direction per cycle).
// The three perturbation strategies of Sec. 5: (1) a random vector in the ball of radius pace, all
// homogeneous coordinates alike; (2) only the weight coordinate; (3) the weight coordinate scaled by
// lambda. Random numbers: std::mt19937_64 (a fully specified engine) mapped to doubles by our own
// conversion and rejection sampling, so a seed gives the same net on every platform.
#include <cstdint>
#include <random>
#include <vector>

#include "src/ortho/edge_angles.hpp"

namespace cg::ortho {

enum class Perturbation {
  Isotropic = 1,     ///< strategy 1: r uniform in the ball |r| <= pace
  WeightOnly = 2,    ///< strategy 2: r = (0, .., 0, r_w), |r_w| <= pace
  ScaledWeight = 3,  ///< strategy 3: (r_c, lambda r_w) with (r_c, r_w) uniform in the ball
};

enum class SweepOrder { LeftToRight, ZigZag };

struct MonteCarloOptions {
  Perturbation perturbation = Perturbation::Isotropic;
  double weight_scale = 1.0;        ///< lambda of strategy 3, > 0
  SweepOrder sweep = SweepOrder::ZigZag;
  int max_cycles = 20;              ///< the paper: "5 to 20 cycles provided very good performance"
  int attempts_per_set = 10;        ///< attempts before the pace is reduced
  double initial_pace = 0.05;       ///< relative to the size of the net (largest homogeneous pole of thread 0)
  double pace_reduction = 0.5;      ///< factor applied when a set fails, in (0, 1)
  double accuracy = 1e-7;           ///< a visit ends when pace < accuracy (relative to the net size)
  int max_attempts_per_visit = 1000;  ///< safeguard (not in the paper): a visit that keeps improving ends here
  double target_score = 0.0;        ///< stop after a cycle that reaches it
  std::uint64_t seed = 1;
  int panels = 8, nodes_per_panel = 8;  ///< quadrature of the score (composite Gauss-Legendre)
};

struct MonteCarloReport {
  int cycles = 0;
  long attempts = 0;                 ///< scored attempts (perturbations with a non-positive weight count too)
  long accepted = 0;
  double start_score = 0, score = 0;
  std::vector<double> cycle_scores;  ///< score after each cycle
  std::vector<long> cycle_attempts;  ///< cumulative attempts after each cycle
};

/// The optimiser as an object: run() or cycle() by cycle; done() after max_cycles or target_score.
template <int Dim>
class MonteCarloContinuation {
 public:
  using HPoint = Eigen::Matrix<double, Dim + 1, 1>;

  /// Throws InvalidGeometry for invalid options or a start net whose thread-1 weights are not positive.
  MonteCarloContinuation(const ContinuationNet<Dim>& start, const PerformanceMap& eta, const MonteCarloOptions& options);

  void cycle();
  void run();
  /// Indices of thread-1 points in the order cycle `c` (0-based) visits them.
  std::vector<int> sweep_order(int c) const;
  bool done() const { return done_; }
  const ContinuationNet<Dim>& net() const { return net_; }
  const MonteCarloReport& report() const { return report_; }
  const EdgeAngleSampler<Dim>& sampler() const { return sampler_; }

 private:
  void visit(int i);
  HPoint random_vector(double pace);
  double uniform();  // [0, 1), 53 bits

  ContinuationNet<Dim> net_;
  EdgeAngleSampler<Dim> sampler_;
  MonteCarloOptions opt_;
  typename EdgeAngleSampler<Dim>::Vectors V_, trial_;
  double score_ = 0, size_ = 1;
  std::mt19937_64 rng_;
  MonteCarloReport report_;
  bool done_ = false;
};

extern template class MonteCarloContinuation<2>;
extern template class MonteCarloContinuation<3>;

}  // namespace cg::ortho
