#pragma once
// Mathematical constants shared by the whole code base (C++17 has no std::numbers).

namespace cg {

/// pi to the precision of a double (the literal has more digits than a double holds; the nearest double
/// is the same as std::acos(-1.0) and M_PI).
inline constexpr double kPi = 3.14159265358979323846;

}  // namespace cg
