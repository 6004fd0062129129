// The shared number formatter of error messages (src/core/format.hpp): shortest round-trip text.
#define BOOST_TEST_MODULE format
#include <boost/test/unit_test.hpp>

#include <cmath>
#include <limits>
#include <string>

#include "src/core/format.hpp"
#include "support/random_geometry.hpp"

using cg::format_number;

BOOST_AUTO_TEST_CASE(shortest_text_of_typical_values) {
  BOOST_TEST(format_number(0.0) == "0");
  BOOST_TEST(format_number(1e-12) == "1e-12");
  BOOST_TEST(format_number(0.1) == "0.1");
  BOOST_TEST(format_number(-2.5) == "-2.5");
  BOOST_TEST(format_number(275.0) == "275");
  BOOST_TEST(format_number(100000.0) == "100000");  // plain notation in [1e-4, 1e15), not "1e+05"
  BOOST_TEST(format_number(1e-4) == "0.0001");
  BOOST_TEST(format_number(1e20) == "1e+20");
  BOOST_TEST(format_number(0.40325) == "0.40325");  // not "0.403250" (six fixed decimals)
  BOOST_TEST(format_number(1.0 / 3.0) == "0.3333333333333333");
  BOOST_TEST(format_number(std::numeric_limits<double>::infinity()) == "inf");
  BOOST_TEST(format_number(std::nan("")) == "nan");
}

// Property: the text parses back to the identical double (10 000 random values over 600 decades).
BOOST_AUTO_TEST_CASE(round_trip_random_values) {
  cg::test::Rng r(3);
  for (int i = 0; i < 10000; ++i) {
    const double x = (r.coin() ? -1 : 1) * r.uniform(1, 10) * std::pow(10.0, r.integer(-300, 300));
    const std::string t = format_number(x);
    BOOST_TEST(std::stod(t) == x, t);
    BOOST_TEST(t.size() <= 24u);
  }
}
