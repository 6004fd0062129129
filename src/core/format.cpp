#include "src/core/format.hpp"

#include <charconv>
#include <cmath>
#include <string>
#include <system_error>

namespace cg {
namespace {

enum class Rounding { nearest, down, up };

constexpr int kDigits = 4;   // what people read
constexpr int kMaxDigits = 17;  // enough to tell any two doubles apart

double parse(const char* first, const char* last) {
  double y = 0;
  std::from_chars(first, last, y);
  return y;
}

// x rounded to `digits` significant decimal digits: to the nearest, or down / up (toward -inf / +inf)
// so that the result never passes x. The result is the double nearest to a decimal of `digits` digits.
double round_significant(double x, int digits, Rounding rounding) {
  if (!std::isfinite(x) || x == 0) return x;
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, x, std::chars_format::scientific, digits - 1);
  const double y = parse(buf, r.ptr);
  if (rounding == Rounding::nearest || (rounding == Rounding::down ? y <= x : y >= x)) return y;
  // Nearest went past x: step one unit of the last digit back. buf is "[-]d.ddde[+-]xx".
  const char* p = buf;
  const bool negative = *p == '-';
  if (negative) ++p;
  long long m = 0;
  for (; *p != 'e'; ++p)
    if (*p != '.') m = 10 * m + (*p - '0');
  int e = 0;
  std::from_chars(p + 1 + (p[1] == '+'), r.ptr, e);
  e -= digits - 1;  // value = m * 10^e
  const bool magnitude_down = (rounding == Rounding::down) != negative;
  long long lowest = 1;
  for (int i = 1; i < digits; ++i) lowest *= 10;
  if (magnitude_down && m == lowest) {
    m = 10 * lowest - 1;  // 1.000e0 -> 9.999e-1, not 0.999
    --e;
  } else {
    m += magnitude_down ? -1 : 1;
  }
  const std::string text = (negative ? "-" : "") + std::to_string(m) + "e" + std::to_string(e);
  return parse(text.data(), text.data() + text.size());
}

Rounding toward(Allowed side) {
  switch (side) {
    case Allowed::below: return Rounding::down;
    case Allowed::above: return Rounding::up;
    case Allowed::near: break;
  }
  return Rounding::nearest;
}

std::string rounded_text(double x, int digits, Rounding rounding) {
  return format_round_trip(round_significant(x, digits, rounding));
}

}  // namespace

std::string format_round_trip(double x) {
  char buf[400];  // fixed notation of a value below 1e15 with its shortest digits fits easily
  const double a = std::fabs(x);
  const bool plain = a == 0 || (a >= 1e-4 && a < 1e15);
  const auto r = plain ? std::to_chars(buf, buf + sizeof buf, x, std::chars_format::fixed)
                       : std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, r.ptr);
}

std::string format_number(double x) { return rounded_text(x, kDigits, Rounding::nearest); }

std::string format_limit(double limit, Allowed side) { return rounded_text(limit, kDigits, toward(side)); }

ValueLimitText format_value_limit(double value, double limit, Allowed side) {
  ValueLimitText t{format_number(value), format_limit(limit, side)};
  if (value == limit) return t;
  for (int digits = kDigits + 1; t.value == t.limit && digits <= kMaxDigits; ++digits)
    t = {rounded_text(value, digits, Rounding::nearest), rounded_text(limit, digits, toward(side))};
  return t;
}

ValueRangeText format_value_range(double value, double lo, double hi) {
  if (value > hi) {
    const ValueLimitText t = format_value_limit(value, hi, Allowed::below);
    return {t.value, format_limit(lo, Allowed::above), t.limit};
  }
  if (value < lo) {
    const ValueLimitText t = format_value_limit(value, lo, Allowed::above);
    return {t.value, t.limit, format_limit(hi, Allowed::below)};
  }
  return {format_number(value), format_limit(lo, Allowed::above), format_limit(hi, Allowed::below)};
}

}  // namespace cg
