#pragma once
// The one number formatter of CoolingGen's messages: the shortest text that parses back to the same
// double (std::to_chars without a precision, C++17 [utility.to.chars]), so a message shows exactly the
// value the code compared or the user gave ("tolerance 1e-12", "u = 0.30000000000000004", "0.4"),
// never a rounded "0.000000" or a padded "0.403250".
#include <charconv>
#include <string>

namespace cg {

/// Shortest round-trip text of x: plain notation for magnitudes in [1e-4, 1e15) ("100000", "0.0001",
/// "275"), exponent notation outside ("1e-12", "1e+20"); "inf", "-inf", "nan".
inline std::string format_number(double x) {
  char buf[400];  // fixed notation of a value below 1e15 with its shortest digits fits easily
  const double a = x < 0 ? -x : x;
  const bool plain = a == 0 || (a >= 1e-4 && a < 1e15);
  const auto r = plain ? std::to_chars(buf, buf + sizeof buf, x, std::chars_format::fixed)
                       : std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, r.ptr);
}

}  // namespace cg
