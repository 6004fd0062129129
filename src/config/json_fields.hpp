#pragma once
// Typed, range-checked reading of a JSON document that knows each value's path, so every error
// names the field ("sections[2].parametric.max_thickness: must be in (0, 40) mm, got -1").
#include <nlohmann/json.hpp>

#include <Eigen/Core>
#include <cmath>
#include <initializer_list>
#include <string>
#include <vector>

#include "src/config/config_error.hpp"

namespace cg::config {

/// Numeric interval; open ends exclude the bound. Infinite bounds are allowed.
struct Range {
  double lo, hi;
  bool lo_open = false, hi_open = false;
  bool contains(double x) const;
  /// "[0, 1]", "(0, 40)", "> 0" ... as told to a refused `value`: bounds rounded inward, the bound
  /// the value passes with as many digits as tell it from the value (src/core/format.hpp).
  std::string describe(double value) const;
};
inline Range closed(double lo, double hi) { return {lo, hi, false, false}; }
inline Range open(double lo, double hi) { return {lo, hi, true, true}; }
Range positive(double hi = HUGE_VAL);  ///< (0, hi]

[[noreturn]] void fail(const std::string& path, const std::string& what);

class Field {
 public:
  Field(const nlohmann::json& value, std::string path) : j_(&value), path_(std::move(path)) {}
  const std::string& path() const { return path_; }
  const nlohmann::json& json() const { return *j_; }

  bool is_object() const { return j_->is_object(); }
  bool is_array() const { return j_->is_array(); }
  bool is_number() const { return j_->is_number(); }

  /// Requires an object whose keys are all in `allowed`.
  void expect_object(std::initializer_list<const char*> allowed) const;
  bool has(const char* key) const { return j_->is_object() && j_->contains(key); }
  Field at(const char* key) const;  ///< required member
  Field item(std::size_t i) const;  ///< array element (after expect_array)
  /// Requires an array with size in [min_size, max_size]; returns its size.
  std::size_t expect_array(std::size_t min_size, std::size_t max_size = static_cast<std::size_t>(-1)) const;

  double number(const Range& range, const char* unit = "") const;
  int integer(int lo, int hi) const;
  std::string string() const;  ///< non-empty string
  bool boolean() const;        ///< true or false (not 0/1, not "true")
  /// String that must be one of `choices` (exact match); returns its index.
  int choice(std::initializer_list<const char*> choices) const;

  /// Optional members with defaults.
  double number_or(const char* key, double fallback, const Range& range, const char* unit = "") const;
  int integer_or(const char* key, int fallback, int lo, int hi) const;
  bool boolean_or(const char* key, bool fallback) const;

  /// [x, y] pair of finite numbers.
  Eigen::Vector2d pair() const;

 private:
  const nlohmann::json* j_;
  std::string path_;
};

/// JSON type name for messages ("object", "array", "string", "number", "boolean", "null").
std::string json_type_name(const nlohmann::json& j);

}  // namespace cg::config
