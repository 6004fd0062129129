#pragma once
// Error types of CoolingGen. Every invalid input is reported by an exception whose message names
// the offending quantity and the allowed range; nothing in the library aborts on bad input.
#include <stdexcept>
#include <string>

namespace cg {

/// Base class of all CoolingGen errors.
class Error : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A geometric definition is invalid (knots, poles, weights, degree, parameter out of domain ...).
class InvalidGeometry : public Error {
 public:
  using Error::Error;
};

/// An algorithm could not produce a result for valid input (e.g. no fillet of this radius exists).
class AlgorithmFailure : public Error {
 public:
  using Error::Error;
};

/// Throws InvalidGeometry(message) unless `condition` holds.
inline void require(bool condition, const std::string& message) {
  if (!condition) throw InvalidGeometry(message);
}

/// Throws InvalidGeometry naming the argument and its range unless 0 <= order <= 25 (kMaxDegree:
/// derivatives above the degree vanish, and higher orders are never needed).
void check_derivative_order(int order, const char* what);

}  // namespace cg
