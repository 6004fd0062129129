#pragma once
// The one number formatter of CoolingGen's messages: the shortest text that parses back to the same
// double (std::to_chars without a precision, C++17 [utility.to.chars]), so a message shows the value
// the code compared ("tolerance 1e-12", "u = 0.30000000000000004"), never a rounded "0.000000".
#include <charconv>
#include <string>

namespace cg {

/// Shortest round-trip text of x ("1e-12", "0.5", "275", "-3e-09", "inf", "nan").
inline std::string format_number(double x) {
  char buf[32];  // the longest shortest form, e.g. "-2.2250738585072014e-308", is 24 characters
  const auto r = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, r.ptr);
}

}  // namespace cg
