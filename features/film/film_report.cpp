#include "features/film/film_report.hpp"

#include <cmath>
#include <map>

namespace cg::features {
namespace {

// JSON has no infinity: "none near" becomes null.
nlohmann::json finite_or_null(double x) { return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr); }

}  // namespace

void summarise_film_report(FilmReport& rep, const std::vector<std::pair<std::string, double>>& row_pitch) {
  rep.rows.clear();
  rep.chambers.clear();
  std::map<std::string, std::size_t> row_index, chamber_index;
  for (const auto& [name, pitch] : row_pitch) {
    row_index[name] = rep.rows.size();
    RowMeasure r;
    r.name = name;
    r.pitch = pitch;
    rep.rows.push_back(r);
  }
  for (const HoleMeasure& h : rep.holes) {
    auto it = row_index.find(h.row);
    if (it == row_index.end()) {
      it = row_index.emplace(h.row, rep.rows.size()).first;
      rep.rows.push_back(RowMeasure{h.row});
    }
    RowMeasure& r = rep.rows[it->second];
    ++r.holes;
    r.breakout_width += h.breakout_width;
    r.min_ligament = std::min(r.min_ligament, h.ligament);
    r.metering_area += h.metering_area;
    auto ct = chamber_index.find(h.chamber);
    if (ct == chamber_index.end()) {
      ct = chamber_index.emplace(h.chamber, rep.chambers.size()).first;
      rep.chambers.push_back(ChamberFeed{h.chamber});
    }
    ++rep.chambers[ct->second].holes;
    rep.chambers[ct->second].metering_area += h.metering_area;
    rep.min_ligament = std::min(rep.min_ligament, h.ligament);
  }
  for (RowMeasure& r : rep.rows) {
    if (r.holes > 0) r.breakout_width /= r.holes;
    r.coverage = r.pitch > 0 ? r.breakout_width / r.pitch : 0;
  }
}

nlohmann::json FilmReport::to_json() const {
  nlohmann::json j;
  nlohmann::json hs = nlohmann::json::array();
  for (const HoleMeasure& h : holes)
    hs.push_back({{"name", h.name},
                  {"row", h.row},
                  {"chamber", h.chamber},
                  {"shape", h.shape},
                  {"span", h.span},
                  {"chord", h.chord},
                  {"exit_mm", {h.exit[0], h.exit[1], h.exit[2]}},
                  {"axis", {h.axis[0], h.axis[1], h.axis[2]}},
                  {"diameter_mm", h.diameter},
                  {"inclination_deg", h.inclination_deg},
                  {"length_mm", h.length},
                  {"length_d", h.length_d},
                  {"metering_length_mm", h.metering_length},
                  {"metering_length_d", h.metering_length_d},
                  {"diffuser_length_mm", h.diffuser_length},
                  {"metering_area_mm2", h.metering_area},
                  {"exit_area_mm2", h.exit_area},
                  {"area_ratio", h.area_ratio},
                  {"footprint_area_mm2", h.footprint_area},
                  {"breakout_width_mm", h.breakout_width},
                  {"expected_volume_mm3", h.expected_volume},
                  {"measured_volume_mm3", finite_or_null(h.measured_volume)},
                  {"volume_passed", h.volume_passed},
                  {"ligament_mm", finite_or_null(h.ligament)},
                  {"ligament_to", h.ligament_to},
                  {"obstacle_ligament_mm", finite_or_null(h.obstacle_ligament)},
                  {"nearest_obstacle", h.nearest_obstacle}});
  j["holes"] = hs;
  nlohmann::json rs = nlohmann::json::array();
  for (const RowMeasure& r : rows)
    rs.push_back({{"name", r.name},
                  {"holes", r.holes},
                  {"pitch_mm", r.pitch},
                  {"breakout_width_mm", r.breakout_width},
                  {"coverage", r.coverage},
                  {"min_ligament_mm", finite_or_null(r.min_ligament)},
                  {"metering_area_mm2", r.metering_area}});
  j["rows"] = rs;
  nlohmann::json cs = nlohmann::json::array();
  for (const ChamberFeed& c : chambers)
    cs.push_back({{"chamber", c.chamber}, {"holes", c.holes}, {"metering_area_mm2", c.metering_area}});
  j["chambers"] = cs;
  nlohmann::json is = nlohmann::json::array();
  for (const InsertMeasure& i : inserts)
    is.push_back({{"name", i.name},
                  {"chamber", i.chamber},
                  {"gap_mm", i.gap},
                  {"measured_gap_mm", i.measured_gap},
                  {"sheet_thickness_mm", i.sheet_thickness},
                  {"measured_sheet_min_mm", i.measured_sheet_min},
                  {"measured_sheet_max_mm", i.measured_sheet_max},
                  {"volume_mm3", i.volume},
                  {"expected_volume_mm3", i.expected_volume},
                  {"jet_holes", i.jet_holes},
                  {"jet_area_mm2", i.jet_area},
                  {"hub_open", i.hub_open},
                  {"tip_open", i.tip_open}});
  j["inserts"] = is;
  j["hole_count"] = holes.size();
  j["min_ligament_mm"] = finite_or_null(min_ligament);
  j["configured_min_ligament_mm"] = configured_min_ligament;
  j["tool_clusters"] = tool_clusters;
  j["drilled_holes"] = drilled_holes;
  j["boolean_runs"] = boolean_runs;
  nlohmann::json t = nlohmann::json::object();
  for (const auto& [stage, s] : seconds) t[stage + "_s"] = s;
  j["seconds"] = t;
  return j;
}

}  // namespace cg::features
