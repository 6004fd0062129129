// The shared number formatter of messages (src/core/format.hpp): 4 significant digits, limits rounded
// toward their allowed side, more digits only where a value and its limit would print alike.
#define BOOST_TEST_MODULE format
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <limits>
#include <string>

#include "src/core/format.hpp"
#include "support/random_geometry.hpp"

using cg::Allowed;
using cg::format_limit;
using cg::format_number;
using cg::format_round_trip;
using cg::format_value_limit;

BOOST_AUTO_TEST_CASE(four_significant_digits) {
  BOOST_TEST(format_number(0.0) == "0");
  BOOST_TEST(format_number(1e-12) == "1e-12");
  BOOST_TEST(format_number(0.1) == "0.1");
  BOOST_TEST(format_number(-2.5) == "-2.5");
  BOOST_TEST(format_number(275.0) == "275");
  BOOST_TEST(format_number(100000.0) == "100000");  // plain notation in [1e-4, 1e15), not "1e+05"
  BOOST_TEST(format_number(123456.0) == "123500");
  BOOST_TEST(format_number(1e-4) == "0.0001");
  BOOST_TEST(format_number(1e20) == "1e+20");
  BOOST_TEST(format_number(1.0 / 3.0) == "0.3333");
  BOOST_TEST(format_number(0.5035133386922451) == "0.5035");  // the message of issue 30
  BOOST_TEST(format_number(0.08503507948668465) == "0.08504");
  BOOST_TEST(format_number(0.99996) == "1");
  BOOST_TEST(format_number(std::numeric_limits<double>::infinity()) == "inf");
  BOOST_TEST(format_number(std::nan("")) == "nan");
}

BOOST_AUTO_TEST_CASE(limits_round_toward_the_allowed_side) {
  BOOST_TEST(format_limit(0.5035133386922451, Allowed::below) == "0.5035");
  BOOST_TEST(format_limit(0.5035133386922451, Allowed::above) == "0.5036");
  BOOST_TEST(format_limit(0.50356, Allowed::below) == "0.5035");  // nearest would be 0.5036, refused
  BOOST_TEST(format_limit(0.99996, Allowed::below) == "0.9999");  // not "1", not "0.999"
  BOOST_TEST(format_limit(-0.40509, Allowed::above) == "-0.405");
  BOOST_TEST(format_limit(-0.40509, Allowed::below) == "-0.4051");
  BOOST_TEST(format_limit(1.0, Allowed::below) == "1");  // 4 digits or fewer: itself
  BOOST_TEST(format_limit(0.1, Allowed::above) == "0.1");
}

// Property: a value at the printed limit lies on the allowed side (10 000 random limits, 600 decades).
BOOST_AUTO_TEST_CASE(printed_limits_are_allowed) {
  cg::test::Rng r(3);
  for (int i = 0; i < 10000; ++i) {
    const double x = (r.coin() ? -1 : 1) * r.uniform(1, 10) * std::pow(10.0, r.integer(-300, 300));
    const double below = std::stod(format_limit(x, Allowed::below)), above = std::stod(format_limit(x, Allowed::above));
    BOOST_TEST(below <= x);
    BOOST_TEST(above >= x);
    BOOST_TEST(std::fabs(below - x) <= 1e-3 * std::fabs(x));  // one unit of the 4th digit at most
    BOOST_TEST(std::fabs(above - x) <= 1e-3 * std::fabs(x));
  }
}

BOOST_AUTO_TEST_CASE(value_and_limit_told_apart) {
  auto t = format_value_limit(0.50352, 0.50351, Allowed::below);
  BOOST_TEST(t.limit == "0.50351");
  BOOST_TEST(t.value == "0.50352");
  t = format_value_limit(1.00001, 1.0, Allowed::below);
  BOOST_TEST(t.limit == "1");
  BOOST_TEST(t.value == "1.00001");
  t = format_value_limit(0.7, 0.5035133386922451, Allowed::below);  // already apart: 4 digits
  BOOST_TEST(t.limit == "0.5035");
  BOOST_TEST(t.value == "0.7");
  t = format_value_limit(0.5, 0.5, Allowed::below);  // the same number: no digits tell them apart
  BOOST_TEST(t.limit == "0.5");
  BOOST_TEST(t.value == "0.5");
  t = format_value_limit(0.40336, 0.40339, Allowed::above);  // both "0.4034" with 4 digits
  BOOST_TEST(t.limit == "0.40339");
  BOOST_TEST(t.value == "0.40336");
}

// Property: data text parses back to the identical double (10 000 random values over 600 decades).
BOOST_AUTO_TEST_CASE(round_trip_random_values) {
  cg::test::Rng r(3);
  for (int i = 0; i < 10000; ++i) {
    const double x = (r.coin() ? -1 : 1) * r.uniform(1, 10) * std::pow(10.0, r.integer(-300, 300));
    const std::string t = format_round_trip(x);
    BOOST_TEST(std::stod(t) == x, t);
    BOOST_TEST(t.size() <= 24u);
  }
}

BOOST_AUTO_TEST_CASE(value_outside_a_range) {
  auto t = cg::format_value_range(2.00001, 1.0, 2.0);
  BOOST_TEST(t.value == "2.00001");
  BOOST_TEST(t.lo == "1");
  BOOST_TEST(t.hi == "2");
  t = cg::format_value_range(0.0999999, 0.1, 0.5035133386922451);
  BOOST_TEST(t.value == "0.0999999");
  BOOST_TEST(t.lo == "0.1");
  BOOST_TEST(t.hi == "0.5035");
}

// A measured value against its expectation (a volume check 1e-4 relative off): digits until they differ.
BOOST_AUTO_TEST_CASE(measured_and_expected_told_apart) {
  const auto t = format_value_limit(12.3456, 12.3454, Allowed::near);  // both "12.35" with 4 digits
  BOOST_TEST(t.value == "12.346");
  BOOST_TEST(t.limit == "12.345");
  BOOST_TEST(format_limit(12.3456, Allowed::near) == "12.35");
}
