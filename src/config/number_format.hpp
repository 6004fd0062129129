#pragma once
// Numbers in messages: the shortest text that reads back as the same double (std::to_chars), so an
// error shows exactly the value given ("0.1", "1e-07", "97"), never a rounded "0.000000".
#include <charconv>
#include <string>

namespace cg::config {

/// Plain notation for magnitudes in [1e-4, 1e15) ("100000", "0.0001"), exponent notation outside.
inline std::string shortest(double x) {
  char buf[400];
  const double a = x < 0 ? -x : x;
  const bool plain = a == 0 || (a >= 1e-4 && a < 1e15);
  const auto r = plain ? std::to_chars(buf, buf + sizeof buf, x, std::chars_format::fixed)
                       : std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, r.ptr);
}

}  // namespace cg::config
