#include "features/passages/passage_report.hpp"

#include <cmath>

namespace cg::features {
namespace {
nlohmann::json number_or_null(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }
}  // namespace

bool PassageReport::passed() const {
  for (const auto& t : thickness)
    if (!t.passed) return false;
  for (const auto& t : tools)
    if (!t.passed) return false;
  return all_chambers_fed;
}

nlohmann::json PassageReport::to_json() const {
  using nlohmann::json;
  json j;
  json th = json::array();
  for (const auto& t : thickness)
    th.push_back({{"feature", t.feature},
                  {"configured_mm", number_or_null(t.configured)},
                  {"min_mm", t.min},
                  {"max_mm", number_or_null(t.max)},
                  {"tolerance_mm", t.tolerance},
                  {"passed", t.passed},
                  {"method", t.method}});
  j["thickness"] = th;
  json ps = json::array();
  for (const auto& p : passages) {
    json secs = json::array();
    for (const auto& c : p.sections)
      secs.push_back({{"span", c.span},
                      {"area_mm2", c.area},
                      {"wetted_perimeter_mm", c.wetted_perimeter},
                      {"hydraulic_diameter_mm", c.hydraulic_diameter}});
    ps.push_back({{"name", p.name}, {"volume_mm3", p.volume}, {"fed_by", p.fed_by}, {"sections", secs}});
  }
  j["passages"] = ps;
  json vs = json::array();
  for (const auto& v : volumes) vs.push_back({{"feature", v.feature}, {"volume_mm3", v.volume}, {"meaning", v.meaning}});
  j["volumes"] = vs;
  json ts = json::array();
  for (const auto& t : tools)
    ts.push_back({{"feature", t.feature},
                  {"expected_mm3", t.expected},
                  {"measured_mm3", t.measured},
                  {"passed", t.passed},
                  {"applied_as", t.how}});
  j["tool_volumes"] = ts;
  j["closed_cavities"] = closed_cavities;
  j["all_chambers_fed"] = all_chambers_fed;
  if (inner_wall_poles_u > 0)
    j["inner_wall"] = {{"poles_u", inner_wall_poles_u}, {"poles_v", inner_wall_poles_v}, {"fit_error_mm", inner_wall_fit_error}};
  j["min_clearance_mm"] = min_clearance;
  json sec = nlohmann::ordered_json::object();
  for (const auto& [stage, s] : seconds) sec[stage] = s;
  j["seconds"] = sec;
  j["passed"] = passed();
  return j;
}

}  // namespace cg::features
