// One-dimensional node distributions (src/grid/distribution.hpp): exact end values, first cell, growth
// limits, Vinokur's end spacings, equidistribution; errors name the reachable range.
#define BOOST_TEST_MODULE grid_distribution
#include <boost/test/unit_test.hpp>

#include <cmath>

#include "src/core/error.hpp"
#include "src/grid/distribution.hpp"

using namespace cg;
using namespace cg::grid;

BOOST_AUTO_TEST_CASE(geometric_then_uniform_properties) {
  for (double r : {1.05, 1.15, 1.3})
    for (int n : {10, 59})
      for (double len : {0.5, 2.0, 10.0}) {
        const double h1 = 0.01;
        if (len < n * h1 || len > geometric_length(h1, r, n)) continue;
        const std::vector<double> s = geometric_then_uniform(h1, r, n, len);
        BOOST_TEST_CONTEXT("r " << r << " n " << n << " len " << len) {
          BOOST_TEST(s.size() == static_cast<std::size_t>(n) + 1);
          BOOST_TEST(s.front() == 0.0);
          BOOST_TEST(s.back() == len);
          BOOST_TEST(std::abs(s[1] - h1) < 1e-15);
          for (int k = 1; k < n; ++k) {
            const double a = s[static_cast<std::size_t>(k)] - s[static_cast<std::size_t>(k) - 1];
            const double b = s[static_cast<std::size_t>(k) + 1] - s[static_cast<std::size_t>(k)];
            BOOST_TEST(b >= a * (1 - 1e-12));   // never shrinking
            BOOST_TEST(b <= a * r * (1 + 1e-12));  // never growing faster than r
          }
        }
      }
}

BOOST_AUTO_TEST_CASE(unreachable_thickness_names_the_range) {
  try {
    geometric_then_uniform(0.01, 1.1, 10, 5.0);
    BOOST_FAIL("no error");
  } catch (const InvalidGeometry& e) {
    const std::string m = e.what();
    BOOST_TEST(m.find("cannot be reached") != std::string::npos);
    BOOST_TEST(m.find("[0.1, 0.1593] mm") != std::string::npos, m);  // 0.159374...: the upper bound rounded down
  }
  BOOST_CHECK_THROW(geometric_then_uniform(0.01, 1.1, 10, 0.05), InvalidGeometry);
}

BOOST_AUTO_TEST_CASE(geometric_fill_hits_the_length) {
  for (double len : {0.5, 1.0, 3.0}) {
    double r = 0;
    const std::vector<double> s = geometric_fill(0.05, 12, len, &r);
    BOOST_TEST(std::abs(s.back() - len) < 1e-14 * len);
    BOOST_TEST(std::abs(s[1] - 0.05) < 1e-9);
    BOOST_TEST(std::abs((s[12] - s[11]) / (s[2] - s[1]) - std::pow(r, 10)) < 1e-9 * std::pow(r, 10));
    BOOST_TEST((len > 0.6 ? r > 1 : r < 1));
  }
}

BOOST_AUTO_TEST_CASE(two_sided_stretching_end_spacings) {
  // Vinokur's function with the corrected end spacings: the end cells match to 1e-9.
  for (auto [d0, d1] : {std::pair{0.2, 0.5}, std::pair{0.05, 0.05}, std::pair{1.0, 2.0}, std::pair{0.1, 3.0}}) {
    const std::vector<double> s = two_sided_stretching(20, 10.0, d0, d1);
    BOOST_TEST_CONTEXT("d0 " << d0 << " d1 " << d1) {
      BOOST_TEST(s.front() == 0.0);
      BOOST_TEST(s.back() == 10.0);
      for (std::size_t k = 1; k < s.size(); ++k) BOOST_TEST(s[k] > s[k - 1]);
      BOOST_TEST(std::abs(s[1] / d0 - 1) < 1e-8);
      BOOST_TEST(std::abs((s[20] - s[19]) / d1 - 1) < 1e-8);
    }
  }
}

BOOST_AUTO_TEST_CASE(equidistribution_of_a_density) {
  // Density 1 on the first half, 3 on the second (linear in between samples): 3x finer cells there.
  std::vector<double> rho;
  for (int k = 0; k <= 400; ++k) rho.push_back(k < 200 ? 1.0 : 3.0);
  const std::vector<double> s = equidistribute(rho, 40, 2.0);
  BOOST_TEST(s.front() == 0.0);
  BOOST_TEST(s.back() == 2.0);
  BOOST_TEST(std::abs((s[2] - s[1]) / (s[39] - s[38]) - 3.0) < 1e-9);
  // Uniform density: uniform nodes.
  const std::vector<double> u = equidistribute(std::vector<double>(11, 2.5), 8, 4.0);
  for (int k = 0; k <= 8; ++k) BOOST_TEST(std::abs(u[static_cast<std::size_t>(k)] - 0.5 * k) < 1e-14);
}
