#pragma once
// Numbers in messages: the shortest text that reads back as the same double (std::to_chars), so an
// error shows exactly the value given ("0.1", "1e-07", "97"), never a rounded "0.000000".
#include <charconv>
#include <string>

namespace cg::config {

inline std::string shortest(double x) {
  char buf[32];
  const auto r = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, r.ptr);
}

}  // namespace cg::config
