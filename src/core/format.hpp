#pragma once
// The one number formatter of CoolingGen's messages. People read four significant digits, so a message
// shows a value rounded to 4 significant digits ("0.5035", "275", "1e-12"); a limit is rounded toward
// its allowed side, so that following the advice works (a value at the printed number is accepted:
// "< 0.5035" for a limit 0.50351334, "> 0.4033" for 0.40325); where a given value and its limit would
// print alike, both get as many more digits as tell them apart ("must be < 0.50351 mm, got 0.50352").
// Distances in messages are never negative: a caller words an overlap as such ("overlaps rib_1 by 0.405
// mm"). Data written for programs (CSV cells, command-line arguments) keeps every digit:
// format_round_trip.
#include <string>

namespace cg {

/// Which side of a limit the allowed values lie on: `below` for "must be < / <= / at most limit",
/// `above` for "must be > / >= / at least limit", `near` for an expected value that a measured one
/// must match (printed to the nearest, like a value).
enum class Allowed { below, above, near };

/// x with 4 significant digits, trailing zeros dropped: plain notation for magnitudes in [1e-4, 1e15)
/// ("0.5035", "123500", "0.0001"), exponent notation outside ("1e-12", "1.235e+20"); "inf", "-inf",
/// "nan".
std::string format_number(double x);

/// A limit with 4 significant digits, rounded toward the allowed side: the printed number is never on
/// the refused side of `limit` ("< 0.5035" for 0.50351334, "> 0.4033" for 0.40325; a limit that has 4
/// digits or fewer prints as itself).
std::string format_limit(double limit, Allowed side);

/// The texts of a given value and its limit in one message.
struct ValueLimitText {
  std::string value;
  std::string limit;
};

/// `value` as format_number, `limit` as format_limit, both with as many more significant digits (up to
/// 17) as it takes to print them differently; equal numbers print with 4 digits.
ValueLimitText format_value_limit(double value, double limit, Allowed side);

/// The texts of a given value and the range [lo, hi] it must lie in (open or closed alike): lo rounded
/// up, hi rounded down, and the bound that the value passes told apart from it as format_value_limit.
struct ValueRangeText {
  std::string value;
  std::string lo;
  std::string hi;
};
ValueRangeText format_value_range(double value, double lo, double hi);

/// Shortest text that parses back to the same double (for data, never for messages): "0.1",
/// "0.30000000000000004", "1e-12".
std::string format_round_trip(double x);

}  // namespace cg
