#include "features/passages/passage_report.hpp"

#include <cmath>
#include <limits>

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

nlohmann::ordered_json PassageReport::to_json() const {
  using nlohmann::json;
  json j;  // keys sorted (std::map), as report.json has always shown them
  json th = json::array();
  for (const auto& t : thickness)
    th.push_back({{"feature", t.feature},
                  {"configured_mm", number_or_null(t.configured)},
                  {"min_mm", number_or_null(t.min)},
                  {"max_mm", number_or_null(t.max)},
                  {"tolerance_mm", number_or_null(t.tolerance)},
                  {"passed", t.passed},
                  {"method", t.method}});
  j["thickness"] = th;
  json ps = json::array();
  for (const auto& p : passages) {
    json secs = json::array();
    for (const auto& c : p.sections)
      secs.push_back({{"span", number_or_null(c.span)},
                      {"area_mm2", number_or_null(c.area)},
                      {"wetted_perimeter_mm", number_or_null(c.wetted_perimeter)},
                      {"hydraulic_diameter_mm", number_or_null(c.hydraulic_diameter)}});
    ps.push_back({{"name", p.name}, {"volume_mm3", number_or_null(p.volume)}, {"fed_by", p.fed_by}, {"sections", secs}});
  }
  j["passages"] = ps;
  json vs = json::array();
  for (const auto& v : volumes) vs.push_back({{"feature", v.feature}, {"volume_mm3", number_or_null(v.volume)}, {"meaning", v.meaning}});
  j["volumes"] = vs;
  json ts = json::array();
  for (const auto& t : tools)
    ts.push_back({{"feature", t.feature},
                  {"expected_mm3", number_or_null(t.expected)},
                  {"measured_mm3", number_or_null(t.measured)},
                  {"passed", t.passed},
                  {"applied_as", t.how}});
  j["tool_volumes"] = ts;
  json pt = json::array();
  for (const auto& p : perturbed) pt.push_back({{"feature", p.feature}, {"change", p.change}, {"geometry_changed", p.geometry_changed}});
  j["perturbed"] = pt;
  j["closed_cavities"] = closed_cavities;
  j["all_chambers_fed"] = all_chambers_fed;
  if (inner_wall_poles_u > 0)
    j["inner_wall"] = {{"poles_u", inner_wall_poles_u}, {"poles_v", inner_wall_poles_v}, {"fit_error_mm", number_or_null(inner_wall_fit_error)}};
  j["min_clearance_mm"] = number_or_null(min_clearance);
  j["wall_clearance_mm"] = number_or_null(wall_clearance);
  j["passed"] = passed();
  j["seconds"] = nullptr;  // its place among the sorted keys
  nlohmann::ordered_json out;
  for (const auto& [key, value] : j.items()) {
    if (key != "seconds") {
      out[key] = value;
      continue;
    }
    nlohmann::ordered_json& sec = out[key] = nlohmann::ordered_json::object();  // in run order
    for (const auto& [stage, s] : seconds) sec[stage] = number_or_null(s);
  }
  return out;
}

PassageReport PassageReport::from_json(const nlohmann::ordered_json& j) {
  const auto num = [](const nlohmann::ordered_json& v) { return v.is_null() ? std::numeric_limits<double>::quiet_NaN() : v.get<double>(); };
  const auto str = [](const nlohmann::ordered_json& v) { return v.get<std::string>(); };
  PassageReport r;
  for (const auto& t : j.at("thickness"))
    r.thickness.push_back({str(t.at("feature")), num(t.at("configured_mm")), num(t.at("min_mm")), num(t.at("max_mm")),
                           num(t.at("tolerance_mm")), t.at("passed").get<bool>(), str(t.at("method"))});
  for (const auto& p : j.at("passages")) {
    PassageMeasure m{str(p.at("name")), num(p.at("volume_mm3")), str(p.at("fed_by")), {}};
    for (const auto& c : p.at("sections"))
      m.sections.push_back({num(c.at("span")), num(c.at("area_mm2")), num(c.at("wetted_perimeter_mm")), num(c.at("hydraulic_diameter_mm"))});
    r.passages.push_back(std::move(m));
  }
  for (const auto& v : j.at("volumes")) r.volumes.push_back({str(v.at("feature")), num(v.at("volume_mm3")), str(v.at("meaning"))});
  for (const auto& t : j.at("tool_volumes"))
    r.tools.push_back({str(t.at("feature")), num(t.at("expected_mm3")), num(t.at("measured_mm3")), t.at("passed").get<bool>(),
                       str(t.at("applied_as"))});
  for (const auto& p : j.at("perturbed")) r.perturbed.push_back({str(p.at("feature")), str(p.at("change")), p.at("geometry_changed").get<bool>()});
  r.closed_cavities = j.at("closed_cavities").get<int>();
  r.all_chambers_fed = j.at("all_chambers_fed").get<bool>();
  if (j.contains("inner_wall")) {
    const auto& w = j.at("inner_wall");
    r.inner_wall_poles_u = w.at("poles_u").get<int>();
    r.inner_wall_poles_v = w.at("poles_v").get<int>();
    r.inner_wall_fit_error = num(w.at("fit_error_mm"));
  }
  r.min_clearance = num(j.at("min_clearance_mm"));
  r.wall_clearance = num(j.at("wall_clearance_mm"));
  for (const auto& [stage, s] : j.at("seconds").items()) r.seconds.emplace_back(stage, num(s));
  return r;
}

}  // namespace cg::features
