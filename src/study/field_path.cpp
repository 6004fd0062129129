#include "src/study/field_path.hpp"

#include <cctype>

#include "src/config/json_fields.hpp"

namespace cg::study {
namespace {

using nlohmann::json;

std::string step_text(const std::string& prefix, const PathStep& s) {
  if (!s.is_index()) return prefix.empty() ? s.key : prefix + "." + s.key;
  return prefix + "[" + (s.index == PathStep::kEvery ? std::string("*") : std::to_string(s.index)) + "]";
}

struct Walk {
  const FieldPath& path;
  ApplyMode mode;
  const json& value;
  const std::string& field;

  [[noreturn]] void missing(const std::string& where, const std::string& what) const {
    config::fail(field, "'" + path.text + "': " + where + " " + what);
  }

  void leaf(json& node, const std::string& at) const {
    if (mode == ApplyMode::kSet) {
      node = value;
      return;
    }
    if (!node.is_number())
      missing(at, "is " + config::json_type_name(node) + ", an offset needs a number (use mode \"set\")");
    node = node.get<double>() + value.get<double>();
  }

  void step(json& node, std::size_t i, const std::string& at) const {
    const PathStep& s = path.steps[i];
    const bool last = i + 1 == path.steps.size();
    if (s.is_index()) {
      if (!node.is_array()) missing(at.empty() ? "the config" : at, "is " + config::json_type_name(node) + ", not an array");
      if (node.empty()) missing(at, "is an empty array");
      const std::size_t n = node.size();
      const auto visit = [&](std::size_t k) {
        const std::string here = at + "[" + std::to_string(k) + "]";
        last ? leaf(node[k], here) : step(node[k], i + 1, here);
      };
      if (s.index == PathStep::kEvery) {
        for (std::size_t k = 0; k < n; ++k) visit(k);
      } else if (static_cast<std::size_t>(s.index) >= n) {
        missing(at, "has " + std::to_string(n) + " element" + (n == 1 ? "" : "s") + " in the base config, index " +
                        std::to_string(s.index) + " is not in [0, " + std::to_string(n - 1) + "]");
      } else {
        visit(static_cast<std::size_t>(s.index));
      }
      return;
    }
    if (!node.is_object()) missing(at.empty() ? "the config" : at, "is " + config::json_type_name(node) + ", not an object");
    const std::string here = step_text(at, s);
    const auto it = node.find(s.key);
    if (it == node.end()) {
      if (!last || mode == ApplyMode::kOffset) missing(here, "is not in the base config");
      node[s.key] = value;
      return;
    }
    last ? leaf(*it, here) : step(*it, i + 1, here);
  }
};

void collect(const json& node, const FieldPath& p, std::size_t i, const std::string& at, std::vector<std::string>& out) {
  if (i == p.steps.size()) {
    out.push_back(at);
    return;
  }
  const PathStep& s = p.steps[i];
  if (!s.is_index()) {
    if (node.is_object()) collect(node.contains(s.key) ? node.at(s.key) : json(), p, i + 1, step_text(at, s), out);
    return;
  }
  if (!node.is_array()) return;
  for (std::size_t k = 0; k < node.size(); ++k)
    if (s.index == PathStep::kEvery || static_cast<std::size_t>(s.index) == k)
      collect(node[k], p, i + 1, at + "[" + std::to_string(k) + "]", out);
}

}  // namespace

FieldPath parse_field_path(const std::string& text, const std::string& field) {
  FieldPath p{text, {}};
  const auto bad = [&](const std::string& why) {
    config::fail(field, "'" + text + "' is not a config field path (" + why +
                            "; e.g. cooling.core.ribs[1].suction_chord or sections[*].parametric.stagger_deg)");
  };
  std::size_t i = 0;
  const auto is_name = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  while (i < text.size()) {
    if (text[i] == '[') {
      const std::size_t close = text.find(']', i);
      if (close == std::string::npos) bad("'[' without ']'");
      const std::string inside = text.substr(i + 1, close - i - 1);
      PathStep s;
      if (inside == "*") {
        s.index = PathStep::kEvery;
      } else {
        if (inside.empty() || inside.size() > 6) bad("an index is a number of up to 6 digits or *");
        for (char c : inside)
          if (!std::isdigit(static_cast<unsigned char>(c))) bad("an index is a number or *, got '" + inside + "'");
        s.index = std::stol(inside);
      }
      if (p.steps.empty()) bad("it starts with an index");
      p.steps.push_back(s);
      i = close + 1;
      if (i < text.size() && text[i] != '.' && text[i] != '[') bad("'.' or '[' expected after ']'");
      if (i < text.size() && text[i] == '.') ++i;
      continue;
    }
    std::size_t j = i;
    while (j < text.size() && is_name(text[j])) ++j;
    if (j == i) bad("empty or invalid name at character " + std::to_string(i + 1));
    p.steps.push_back({text.substr(i, j - i), 0});
    i = j;
    if (i < text.size() && text[i] == '.') {
      ++i;
      if (i == text.size()) bad("it ends with '.'");
    } else if (i < text.size() && text[i] != '[') {
      bad("unexpected '" + std::string(1, text[i]) + "'");
    }
  }
  if (p.steps.empty()) bad("empty");
  return p;
}

void apply_field(json& doc, const FieldPath& path, ApplyMode mode, const json& value, const std::string& field) {
  Walk{path, mode, value, field}.step(doc, 0, "");
}

std::vector<std::string> concrete_paths(const json& doc, const FieldPath& path) {
  std::vector<std::string> out;
  collect(doc, path, 0, "", out);
  return out;
}

}  // namespace cg::study
