#include "export/report_markdown.hpp"

#include <cstdio>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "export/atomic_file.hpp"
#include "export/version.hpp"

namespace cg::io {
namespace {

using json = nlohmann::ordered_json;

std::string num(const json& v, int digits = 3) {
  if (v.is_number_integer() || v.is_number_unsigned()) return v.dump();
  if (!v.is_number()) return v.is_string() ? v.get<std::string>() : v.dump();
  char b[64];
  const double x = v.get<double>();
  if (x != 0 && (std::abs(x) < 1e-3 || std::abs(x) >= 1e7))
    std::snprintf(b, sizeof b, "%.3e", x);
  else
    std::snprintf(b, sizeof b, "%.*f", digits, x);
  return b;
}

// Cell text: no pipes or newlines inside a table cell.
std::string cell(const json& v) {
  std::string s = v.is_string() ? v.get<std::string>() : (v.is_number() ? num(v) : v.dump());
  for (char& c : s)
    if (c == '|' || c == '\n') c = ' ';
  return s;
}

void table(std::ostringstream& o, const std::vector<std::string>& head, const std::vector<std::vector<std::string>>& rows) {
  o << "|";
  for (const auto& h : head) o << " " << h << " |";
  o << "\n|";
  for (std::size_t i = 0; i < head.size(); ++i) o << "---|";
  o << "\n";
  for (const auto& r : rows) {
    o << "|";
    for (const auto& c : r) o << " " << c << " |";
    o << "\n";
  }
  o << "\n";
}

// A table of an array of flat objects (columns = union of keys in first-seen order).
void object_table(std::ostringstream& o, const json& rows) {
  std::vector<std::string> head;
  std::set<std::string> seen;
  for (const auto& r : rows)
    if (r.is_object())
      for (const auto& [k, v] : r.items())
        if (seen.insert(k).second) head.push_back(k);
  std::vector<std::vector<std::string>> body;
  for (const auto& r : rows) {
    std::vector<std::string> line;
    for (const auto& h : head) line.push_back(r.is_object() && r.contains(h) ? cell(r.at(h)) : "");
    body.push_back(line);
  }
  table(o, head, body);
}

void sections(std::ostringstream& o, const json& secs) {
  o << "## Coolant passages along span\n\nFrom the section cuts of `sections.svg` (straight vane: planes at "
       "the span height; meridional blade: the streamline surfaces of revolution), the same cuts as the "
       "design checks' cross-sections. A passage is a cavity of the blade section, its walls closed over "
       "the holes and slots that cross the cut (those are holes in the metal, counted apart); its area "
       "excludes inserts, its wetted perimeter includes them; D_h = 4 A / P.\n\n";
  std::vector<std::vector<std::string>> rows;
  for (const auto& s : secs) {
    const json& ps = s.value("passages", json::array());
    std::string names, areas, dh, total;
    double sum = 0;
    for (std::size_t i = 0; i < ps.size(); ++i) {
      const std::string sep = i ? ", " : "";
      names += sep + cell(ps[i].value("name", ""));
      areas += sep + num(ps[i].value("area_mm2", 0.0), 2);
      dh += sep + num(ps[i].value("hydraulic_diameter_mm", 0.0), 2);
      sum += ps[i].value("area_mm2", 0.0);
    }
    rows.push_back({num(s.value("span", 0.0), 2), num(s.value("chord_mm", 0.0), 2), num(s.value("metal_area_mm2", 0.0), 2),
                    std::to_string(ps.size()), num(sum, 2), names.empty() ? "-" : names, areas.empty() ? "-" : areas,
                    dh.empty() ? "-" : dh,
                    num(s.value("hole_count", 0)) + " (" + num(s.value("hole_area_mm2", 0.0), 2) + " mm²)"});
  }
  table(o, {"span", "chord mm", "metal area mm²", "passages", "coolant area mm²", "names", "area mm² each", "D_h mm each", "holes"},
        rows);
}

void mesh_section(std::ostringstream& o, const json& m) {
  o << "## Mesh\n\n" << num(m.value("nodes", 0)) << " nodes, " << num(m.value("triangles", 0)) << " boundary triangles, "
    << num(m.value("tetrahedra", 0)) << " tetrahedra, **" << num(m.value("inverted", 0)) << " inverted**, minimum quality "
    << num(m.value("min_quality", 0.0)) << " (" << cell(m.value("quality_measure", "")) << ").\n\n";
  std::vector<std::vector<std::string>> rows;
  for (const auto& r : m.value("regions", json::array()))
    rows.push_back({cell(r.value("name", "")), r.value("fluid", false) ? "fluid" : "solid", num(r.value("tetrahedra", 0)),
                    num(r.value("inverted", 0)), num(r.value("min_quality", 0.0)), num(r.value("mean_quality", 0.0)),
                    num(r.value("mesh_volume_mm3", 0.0), 2), num(r.value("brep_volume_mm3", 0.0), 2)});
  table(o, {"region", "type", "tetrahedra", "inverted", "min quality", "mean quality", "mesh volume mm³", "B-rep volume mm³"}, rows);
  if (m.contains("coolant")) {
    const json& c = m.at("coolant");
    o << "Coolant volume: removed by the features " << num(c.value("removed_volume_mm3", 0.0), 3) << " mm³, minus inserts "
      << num(c.value("insert_volume_mm3", 0.0), 3) << " mm³ = " << num(c.value("expected_volume_mm3", 0.0), 3)
      << " mm³; B-rep " << num(c.value("brep_volume_mm3", 0.0), 3) << " mm³ (relative "
      << num(c.value("brep_vs_expected_relative", 0.0)) << "), mesh " << num(c.value("mesh_volume_mm3", 0.0), 3)
      << " mm³ (relative " << num(c.value("mesh_vs_expected_relative", 0.0)) << ").\n\n";
  }
  rows.clear();
  for (const auto& g : m.value("surface_groups", json::array()))
    rows.push_back({cell(g.value("name", "")), num(g.value("faces", 0)), num(g.value("triangles", 0))});
  if (!rows.empty()) table(o, {"surface group", "faces", "triangles"}, rows);
}

// Coolant flow network (report.json "network", src/network): status, total flow, per chamber, worst margin.
void network_section(std::ostringstream& o, const json& n) {
  o << "## Coolant flow network\n\nCalculiX: **" << cell(n.value("status", "")) << "** (" << cell(n.value("message", ""))
    << "); details in `network_results.json`, the circuit in `network.json` (docs/network.md).\n\n";
  if (!n.contains("total_mass_flow_kg_s")) return;
  o << "Total coolant " << num(n.at("total_mass_flow_kg_s").get<double>() * 1e3) << " g/s";
  if (n.contains("worst_backflow_margin"))
    o << "; worst backflow margin " << num(n.at("worst_backflow_margin")) << " (" << cell(n.value("worst_backflow_row", "")) << ")";
  o << ".\n\n";
  std::vector<std::vector<std::string>> rows;
  const json chambers = n.value("chamber_mass_flow_kg_s", json::object());
  for (const auto& [chamber, flow] : chambers.items())
    rows.push_back({chamber, num(flow.get<double>() * 1e3)});
  if (!rows.empty()) table(o, {"chamber", "coolant g/s"}, rows);
}

// Film cooling (model.cooling.film, features/film/film_report.hpp): rows, chambers fed, inserts, every hole.
// A null ligament means no other hole (or obstacle) is near: "-".
void film_section(std::ostringstream& o, const json& f) {
  const auto lig = [](const json& v) { return v.is_null() ? std::string("-") : num(v); };
  o << "## Film cooling\n\n" << num(f.value("hole_count", 0)) << " holes; least ligament between holes "
    << lig(f.value("min_ligament_mm", json())) << " mm (configured minimum " << num(f.value("configured_min_ligament_mm", 0.0))
    << " mm). Coverage = mean breakout width / pitch along the row.\n\n";
  std::vector<std::vector<std::string>> rows;
  for (const auto& r : f.value("rows", json::array()))
    rows.push_back({cell(r.value("name", "")), num(r.value("holes", 0)), num(r.value("pitch_mm", 0.0)),
                    num(r.value("breakout_width_mm", 0.0)), num(r.value("coverage", 0.0)), lig(r.value("min_ligament_mm", json())),
                    num(r.value("metering_area_mm2", 0.0))});
  table(o, {"row", "holes", "pitch mm", "breakout width mm", "coverage", "min ligament mm", "metering area mm²"}, rows);
  rows.clear();
  for (const auto& c : f.value("chambers", json::array()))
    rows.push_back({cell(c.value("chamber", "")), num(c.value("holes", 0)), num(c.value("metering_area_mm2", 0.0))});
  if (!rows.empty()) table(o, {"chamber", "holes fed", "total metering area mm²"}, rows);
  rows.clear();
  for (const auto& i : f.value("inserts", json::array()))
    rows.push_back({cell(i.value("name", "")), cell(i.value("chamber", "")), num(i.value("gap_mm", 0.0)),
                    num(i.value("measured_gap_mm", 0.0)), num(i.value("sheet_thickness_mm", 0.0)),
                    num(i.value("measured_sheet_min_mm", 0.0)) + " - " + num(i.value("measured_sheet_max_mm", 0.0)),
                    num(i.value("jet_holes", 0)), num(i.value("jet_area_mm2", 0.0))});
  if (!rows.empty())
    table(o, {"insert", "chamber", "gap Z mm", "measured gap mm", "sheet mm", "measured sheet mm", "jets", "jet area mm²"}, rows);
  rows.clear();
  for (const auto& h : f.value("holes", json::array()))
    rows.push_back({"`" + cell(h.value("name", "")) + "`", cell(h.value("chamber", "")), cell(h.value("shape", "")),
                    num(h.value("diameter_mm", 0.0)), num(h.value("inclination_deg", 0.0), 1), num(h.value("length_mm", 0.0)),
                    num(h.value("length_d", 0.0), 2), num(h.value("metering_area_mm2", 0.0)),
                    num(h.value("footprint_area_mm2", 0.0)), num(h.value("expected_volume_mm3", 0.0), 4),
                    num(h.value("measured_volume_mm3", json()), 4)});
  if (!rows.empty())
    table(o, {"hole", "chamber", "shape", "D mm", "inclination deg", "L mm", "L/D", "metering area mm²", "exit footprint mm²",
              "volume mm³ (expected)", "volume mm³ (measured)"},
          rows);
}

}  // namespace

std::string report_markdown(const json& r) {
  std::ostringstream o;
  const json model = r.value("model", json::object());
  const std::string name = model.is_object() && model.contains("name") ? cell(model.at("name")) : "blade";
  o << "# " << name << ": CoolingGen report\n\n";
  o << "Generated by " << kToolName << " " << tool_version() << ". Units: mm, mm², mm³, degrees, seconds. "
    << "Status: **" << (r.value("valid", false) ? "valid" : "INVALID") << "**.\n\n";
  if (model.is_object()) {
    o << "## What was built\n\n";
    std::vector<std::vector<std::string>> rows;
    for (const char* k : {"description", "source", "flow_path", "span_length_mm", "overbuild", "step_schema"})
      if (model.contains(k) && !model.at(k).is_null() && !(model.at(k).is_string() && model.at(k).get<std::string>().empty()))
        rows.push_back({k, cell(model.at(k))});
    if (model.contains("sections")) rows.push_back({"sections", std::to_string(model.at("sections").size())});
    if (model.contains("blade_surface")) {
      const json& s = model.at("blade_surface");
      rows.push_back({"blade surface", "degree " + num(s.value("degree_u", 0)) + " x " + num(s.value("degree_v", 0)) + ", " +
                                           num(s.value("poles_u", 0)) + " x " + num(s.value("poles_v", 0)) + " poles" +
                                           (s.value("rational", false) ? ", rational" : "")});
    }
    table(o, {"item", "value"}, rows);
  }
  if (r.contains("solid")) {
    const json& s = r.at("solid");
    o << "## Solid\n\n";
    std::vector<std::vector<std::string>> rows{{"volume mm³", num(s.value("volume_mm3", 0.0), 4)},
                                               {"surface area mm²", num(s.value("surface_area_mm2", 0.0), 4)},
                                               {"solids", num(s.value("solid_count", 0))},
                                               {"faces", num(s.value("face_count", 0))}};
    if (s.contains("bbox_mm")) rows.push_back({"bounding box size mm", cell(s.at("bbox_mm").value("size", json::array()))});
    table(o, {"quantity", "value"}, rows);
    if (s.contains("faces") && s.at("faces").is_object()) {
      std::map<std::string, int> faces;
      for (const auto& [n, c] : s.at("faces").items()) faces[n] = c.is_number() ? c.get<int>() : 0;
      std::vector<std::vector<std::string>> frows;
      for (const auto& [n, c] : faces) frows.push_back({"`" + n + "`", std::to_string(c)});
      o << "Faces per feature name:\n\n";
      table(o, {"face name", "faces"}, frows);
    }
  }
  if (r.contains("checks")) {
    o << "## Checks\n\n";
    std::vector<std::vector<std::string>> rows;
    for (const auto& [n, c] : r.at("checks").items())
      rows.push_back({"`" + n + "`", c.value("passed", false) ? "passed" : "**FAILED**", cell(c.value("message", ""))});
    table(o, {"check", "result", "measured"}, rows);
  }
  if (r.contains("design_checks") && r.at("design_checks").is_object()) {
    o << "## Design checks\n\n";
    for (const auto& [n, rows] : r.at("design_checks").items()) {
      o << "### " << n << "\n\n";
      if (rows.is_array())
        object_table(o, rows);
      else
        o << "```\n" << rows.dump(2) << "\n```\n\n";
    }
  }
  if (model.is_object() && model.contains("cooling") && model.at("cooling").is_object() && model.at("cooling").contains("film"))
    film_section(o, model.at("cooling").at("film"));
  if (r.contains("network")) network_section(o, r.at("network"));
  if (r.contains("sections") && !r.at("sections").empty()) sections(o, r.at("sections"));
  if (r.contains("mesh")) mesh_section(o, r.at("mesh"));
  if (r.contains("outputs") || r.contains("notes")) {
    o << "## Files\n\n";
    for (const auto& f : r.value("outputs", json::array())) o << "- `" << cell(f) << "`\n";
    for (const auto& n : r.value("notes", json::array())) o << "- note: " << cell(n) << "\n";
    o << "\n";
  }
  if (r.contains("timings_s") && r.at("timings_s").is_object() && !r.at("timings_s").empty()) {
    o << "## Timings\n\n";
    std::vector<std::vector<std::string>> rows;
    for (const auto& [k, v] : r.at("timings_s").items()) rows.push_back({k, num(v)});
    table(o, {"stage", "s"}, rows);
  }
  const json warnings = r.value("warnings", json::array());
  if (!warnings.empty()) {
    o << "## Warnings\n\n";
    for (const auto& w : warnings) o << "- " << cell(w) << "\n";
    o << "\n";
  }
  return o.str();
}

void write_report_markdown(const std::filesystem::path& file, const json& report) {
  const std::string text = report_markdown(report);
  write_atomically(file, [&](const std::filesystem::path& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    out << text;
    out.close();
    if (!out) throw ExportError("cannot write " + tmp.string());
  });
}

}  // namespace cg::io
