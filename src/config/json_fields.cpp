#include "src/config/json_fields.hpp"

#include <cmath>
#include <sstream>

#include "src/core/format.hpp"

namespace cg::config {
namespace {

std::string shown(const nlohmann::json& j) {
  std::string s = j.dump();
  if (s.size() > 40) s = s.substr(0, 37) + "...";
  return s;
}

std::string child(const std::string& path, const char* key) { return path.empty() ? key : path + "." + key; }

}  // namespace

bool Range::contains(double x) const {
  if (!std::isfinite(x)) return false;
  return (lo_open ? x > lo : x >= lo) && (hi_open ? x < hi : x <= hi);
}

std::string Range::describe(double value) const {
  const bool lo_inf = std::isinf(lo), hi_inf = std::isinf(hi);
  if (lo_inf && hi_inf) return "finite";
  const ValueRangeText t = format_value_range(value, lo, hi);
  if (hi_inf) return std::string(lo_open ? "> " : ">= ") + t.lo;
  if (lo_inf) return std::string(hi_open ? "< " : "<= ") + t.hi;
  return std::string(lo_open ? "(" : "[") + t.lo + ", " + t.hi + (hi_open ? ")" : "]");
}

Range positive(double hi) { return {0.0, hi, true, false}; }

void fail(const std::string& path, const std::string& what) { throw ConfigError((path.empty() ? "config" : path) + ": " + what); }

std::string json_type_name(const nlohmann::json& j) {
  if (j.is_number()) return "number";
  return j.type_name();
}

void Field::expect_object(std::initializer_list<const char*> allowed) const {
  if (!j_->is_object()) fail(path_, "must be an object, got " + json_type_name(*j_));
  for (const auto& item : j_->items()) {
    bool ok = false;
    for (const char* a : allowed) ok = ok || item.key() == a;
    if (!ok) {
      std::string list;
      for (const char* a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
      fail(child(path_, item.key().c_str()), "unknown key (allowed here: " + list + ")");
    }
  }
}

Field Field::at(const char* key) const {
  if (!j_->is_object()) fail(path_, "must be an object, got " + json_type_name(*j_));
  const auto it = j_->find(key);
  if (it == j_->end()) fail(child(path_, key), "missing (required)");
  return Field(*it, child(path_, key));
}

Field Field::item(std::size_t i) const { return Field(j_->at(i), path_ + "[" + std::to_string(i) + "]"); }

std::size_t Field::expect_array(std::size_t min_size, std::size_t max_size) const {
  if (!j_->is_array()) fail(path_, "must be an array, got " + json_type_name(*j_));
  const std::size_t n = j_->size();
  if (n < min_size || n > max_size) {
    std::string want = max_size == static_cast<std::size_t>(-1) ? "at least " + std::to_string(min_size)
                       : min_size == max_size                  ? "exactly " + std::to_string(min_size)
                                          : "between " + std::to_string(min_size) + " and " + std::to_string(max_size);
    fail(path_, "must have " + want + " entries, got " + std::to_string(n));
  }
  return n;
}

double Field::number(const Range& range, const char* unit) const {
  if (!j_->is_number()) fail(path_, "must be a number, got " + json_type_name(*j_) + " " + shown(*j_));
  const double x = j_->get<double>();
  if (!range.contains(x))
    fail(path_, "must be " + range.describe(x) + (*unit ? std::string(" ") + unit : "") + ", got " +
                    format_value_range(x, range.lo, range.hi).value);
  return x;
}

// JSON Schema's "integer" is any number with zero fractional part, so 97.0 and 1e2 are integers too.
// Compared as double: exact below 2^53, and larger values are out of any int range anyway.
int Field::integer(int lo, int hi) const {
  const double v = j_->is_number() ? j_->get<double>() : 0.0;
  if (!j_->is_number() || !std::isfinite(v) || std::trunc(v) != v)
    fail(path_, "must be an integer, got " + json_type_name(*j_) + " " + shown(*j_));
  if (v < lo || v > hi) fail(path_, "must be in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got " + shown(*j_));
  return static_cast<int>(v);
}

std::string Field::string() const {
  if (!j_->is_string()) fail(path_, "must be a string, got " + json_type_name(*j_) + " " + shown(*j_));
  std::string s = j_->get<std::string>();
  if (s.empty()) fail(path_, "must not be empty");
  return s;
}

int Field::choice(std::initializer_list<const char*> choices) const {
  const std::string s = j_->is_string() ? j_->get<std::string>() : std::string();
  int i = 0;
  std::string list;
  for (const char* c : choices) {
    if (j_->is_string() && s == c) return i;
    list += (list.empty() ? "\"" : ", \"") + std::string(c) + "\"";
    ++i;
  }
  fail(path_, "must be one of " + list + ", got " + shown(*j_));
}

double Field::number_or(const char* key, double fallback, const Range& range, const char* unit) const {
  return has(key) ? at(key).number(range, unit) : fallback;
}

int Field::integer_or(const char* key, int fallback, int lo, int hi) const {
  return has(key) ? at(key).integer(lo, hi) : fallback;
}

bool Field::boolean() const {
  if (!j_->is_boolean()) fail(path_, "must be true or false, got " + json_type_name(*j_));
  return j_->get<bool>();
}

bool Field::boolean_or(const char* key, bool fallback) const { return has(key) ? at(key).boolean() : fallback; }

Eigen::Vector2d Field::pair() const {
  expect_array(2, 2);
  return {item(0).number(Range{-HUGE_VAL, HUGE_VAL}), item(1).number(Range{-HUGE_VAL, HUGE_VAL})};
}

}  // namespace cg::config
