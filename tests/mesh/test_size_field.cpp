// The graded size field of the mesher (src/mesh/size_field.hpp) against the formula evaluated over every
// sample: the k-d tree's branch and bound prunes only nodes that cannot lower the minimum, so both give
// the same minimum of the same floating-point expressions (compared exactly).
#define BOOST_TEST_MODULE size_field
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <random>

#include "src/mesh/size_field.hpp"

using cg::mesh::GradedSizeField;

namespace {

double brute_force(const std::vector<GradedSizeField::Sample>& samples, double growth, double max_size,
                   const Eigen::Vector3d& x) {
  double h = max_size;
  for (const auto& s : samples) h = std::min(h, s.size + growth * (x - s.point).norm());
  return h;
}

// Samples clustered like feature curves: short circles (holes) of small size plus long lines of larger size.
std::vector<GradedSizeField::Sample> feature_like_samples(std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-20, 20), r(0.1, 0.5), size(0.05, 0.3);
  std::vector<GradedSizeField::Sample> out;
  for (int hole = 0; hole < 60; ++hole) {
    const Eigen::Vector3d c(u(rng), u(rng), u(rng));
    const double radius = r(rng), h = size(rng);
    for (int k = 0; k < 40; ++k) {
      const double a = 2 * 3.14159265358979323846 * k / 40;
      out.push_back({c + radius * Eigen::Vector3d(std::cos(a), std::sin(a), 0), h});
    }
  }
  for (int line = 0; line < 5; ++line) {
    const Eigen::Vector3d a(u(rng), u(rng), u(rng)), b(u(rng), u(rng), u(rng));
    for (int k = 0; k <= 200; ++k) out.push_back({a + (b - a) * (k / 200.0), 0.8});
  }
  return out;
}

}  // namespace

BOOST_AUTO_TEST_CASE(equals_the_minimum_over_all_samples) {
  std::mt19937 rng(7);
  const auto samples = feature_like_samples(rng);
  std::uniform_int_distribution<std::size_t> pick(0, samples.size() - 1);
  for (double growth : {0.1, 0.25, 1.0}) {
    const GradedSizeField field(samples, growth, 1.5);
    std::uniform_real_distribution<double> q(-2 / growth, 2 / growth);
    BOOST_TEST(field.samples() == samples.size());
    int below_max = 0, at_max = 0;
    for (int i = 0; i < 4000; ++i) {
      // Near a sample, out to where the size reaches the cap (1.5 / growth) and beyond.
      const Eigen::Vector3d x = samples[pick(rng)].point + Eigen::Vector3d(q(rng), q(rng), q(rng));
      const double expected = brute_force(samples, growth, 1.5, x);
      BOOST_TEST(field(x) == expected, "growth " << growth << " at " << x.transpose());
      below_max += expected < 1.5;
      at_max += expected == 1.5;
    }
    BOOST_TEST(below_max > 300);  // the queries cover the graded zones
    BOOST_TEST(at_max > 300);     // and the cap beyond them
  }
}

BOOST_AUTO_TEST_CASE(at_a_sample_its_size_and_capped_far_away) {
  const std::vector<GradedSizeField::Sample> samples{{{0, 0, 0}, 0.05}, {{10, 0, 0}, 0.4}};
  const GradedSizeField field(samples, 0.25, 1.5);
  BOOST_TEST(field({0, 0, 0}) == 0.05);
  BOOST_TEST(field({10, 0, 0}) == 0.4);
  BOOST_TEST(field({0, 2, 0}) == 0.05 + 0.25 * 2);
  BOOST_TEST(field({100, 100, 100}) == 1.5);
  const GradedSizeField empty({}, 0.25, 1.5);
  BOOST_TEST(empty({1, 2, 3}) == 1.5);
}
