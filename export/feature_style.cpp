#include "export/feature_style.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <set>

namespace cg::io {
namespace {

// HSV -> RGB (all in [0, 1]).
Colour hsv(double h, double s, double v) {
  const double c = v * s, hp = std::fmod(h, 1.0) * 6, x = c * (1 - std::abs(std::fmod(hp, 2.0) - 1)), m = v - c;
  const int sector = static_cast<int>(hp) % 6;
  const double table[6][3] = {{c, x, 0}, {x, c, 0}, {0, c, x}, {0, x, c}, {x, 0, c}, {c, 0, x}};
  return {table[sector][0] + m, table[sector][1] + m, table[sector][2] + m};
}

}  // namespace

Colour kind_colour(const std::string& kind) {
  // Metal outer surfaces grey/steel; flow-path end walls muted; coolant-wetted features saturated.
  static const std::map<std::string, Colour> fixed = {
      {"blade_wall", {0.72, 0.74, 0.78}}, {"hub", {0.55, 0.55, 0.50}},        {"casing", {0.50, 0.52, 0.58}},
      {"tip_cap", {0.62, 0.60, 0.56}},    {"hub_floor", {0.58, 0.56, 0.52}},  {"chamber", {0.15, 0.45, 0.85}},
      {"rib", {0.90, 0.55, 0.10}},        {"turnaround", {0.10, 0.65, 0.65}}, {"turbulator", {0.80, 0.25, 0.55}},
      {"te_slot", {0.55, 0.30, 0.80}},    {"pin_fin", {0.95, 0.80, 0.10}},    {"film_row", {0.85, 0.15, 0.15}},
      {"showerhead", {0.95, 0.35, 0.20}}, {"insert", {0.20, 0.70, 0.30}}};
  if (const auto it = fixed.find(kind); it != fixed.end()) return it->second;
  // FNV-1a hash of the kind -> hue; saturated and bright enough to stand out from the grey wall.
  std::uint32_t h = 2166136261u;
  for (unsigned char ch : kind) h = (h ^ ch) * 16777619u;
  return hsv((h % 360) / 360.0, 0.75, 0.85);
}

std::string hex_colour(const Colour& c) {
  char buf[8];
  auto byte = [](double v) { return static_cast<int>(std::lround(std::clamp(v, 0.0, 1.0) * 255)); };
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", byte(c[0]), byte(c[1]), byte(c[2]));
  return buf;
}

FeatureTable feature_table(const brep::Part& part) {
  FeatureTable t;
  std::set<std::string> names;
  for (const brep::NamedBody& body : part)
    for (const brep::NamedFace& f : body.geometry.faces) {
      names.insert(f.name);
      const std::string kind = brep::feature_kind(f.name);
      if (t.id_of_kind.emplace(kind, static_cast<int>(t.kinds.size())).second) t.kinds.push_back(kind);
    }
  t.names.assign(names.begin(), names.end());
  for (std::size_t i = 0; i < t.names.size(); ++i) t.id_of_name[t.names[i]] = static_cast<int>(i);
  return t;
}

}  // namespace cg::io
