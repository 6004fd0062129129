#include "src/config/cooling_config.hpp"

#include <cmath>
#include <fstream>
#include <sstream>

#include "src/blade/section.hpp"
#include "src/config/config_error.hpp"
#include "src/config/cooling_film_config.hpp"
#include "src/core/format.hpp"

namespace cg::config {
namespace {

using features::SpanEnd;

blade::ThicknessField wall_thickness(const Field& f) {
  const Range t = positive(20);
  if (f.is_number()) return blade::ThicknessField::constant(f.number(t, "mm"));
  f.expect_object({"spans", "chords", "values"});
  const Field fs = f.at("spans"), fc = f.at("chords"), fv = f.at("values");
  std::vector<double> spans, chords;
  const std::size_t ns = fs.expect_array(1, 50), nc = fc.expect_array(1, 200);
  for (std::size_t i = 0; i < ns; ++i) {
    spans.push_back(fs.item(i).number(closed(0, 1)));
    if (i > 0 && spans[i] <= spans[i - 1]) fail(fs.item(i).path(), "spans must be strictly increasing");
  }
  for (std::size_t j = 0; j < nc; ++j) {
    chords.push_back(fc.item(j).number(closed(-1, 1)));
    if (j > 0 && chords[j] <= chords[j - 1]) fail(fc.item(j).path(), "chords must be strictly increasing");
  }
  fv.expect_array(ns, ns);
  std::vector<std::vector<double>> values(ns);
  for (std::size_t i = 0; i < ns; ++i) {
    const Field row = fv.item(i);
    row.expect_array(nc, nc);
    for (std::size_t j = 0; j < nc; ++j) values[i].push_back(row.item(j).number(t, "mm"));
  }
  return blade::ThicknessField::table(spans, chords, values);
}

features::EndWallDefinition end_wall(const Field& f) {
  f.expect_object({"thickness", "open"});
  features::EndWallDefinition e;
  e.open = f.boolean_or("open", e.open);
  if (e.open) {
    if (f.has("thickness")) fail(f.path() + ".thickness", "an open end has no thickness");
  } else {
    e.thickness = f.at("thickness").number(positive(20), "mm");
  }
  return e;
}

SpanEnd span_end(const Field& f) { return f.choice({"hub", "tip"}) == 0 ? SpanEnd::Hub : SpanEnd::Tip; }

features::RibDefinition rib(const Field& f) {
  f.expect_object({"suction_chord", "pressure_chord", "thickness", "fillet_radius", "turnaround"});
  features::RibDefinition r;
  r.suction_chord = f.at("suction_chord").number(open(0, 1));
  r.pressure_chord = f.at("pressure_chord").number(open(-1, 0));
  r.thickness = f.at("thickness").number(positive(20), "mm");
  r.fillet_radius = f.number_or("fillet_radius", 0, closed(0, 10), "mm");
  if (f.has("turnaround")) {
    const Field t = f.at("turnaround");
    t.expect_object({"end", "gap", "tip_radius"});
    features::TurnaroundDefinition d;
    d.end = span_end(t.at("end"));
    d.gap = t.at("gap").number(positive(200), "mm");
    d.tip_radius = t.number_or("tip_radius", 0.5 * r.thickness, open(0, 10), "mm");
    if (d.tip_radius > 0.5 * r.thickness) {
      const ValueLimitText v = format_value_limit(d.tip_radius, 0.5 * r.thickness, Allowed::below);
      fail(t.path() + ".tip_radius", "must be <= thickness / 2 = " + v.limit + " mm, got " + v.value);
    }
    r.turnaround = d;
  }
  return r;
}

features::InletDefinition inlet(const Field& f) {
  f.expect_object({"chamber", "end", "diameter", "suction_chord", "pressure_chord"});
  features::InletDefinition in;
  in.chamber = f.at("chamber").integer(1, 100);
  if (f.has("end")) in.end = span_end(f.at("end"));
  in.diameter = f.at("diameter").number(positive(50), "mm");
  if (f.has("suction_chord")) in.suction_chord = f.at("suction_chord").number(open(0, 1));
  if (f.has("pressure_chord")) in.pressure_chord = f.at("pressure_chord").number(open(-1, 0));
  return in;
}

features::TurbulatorDefinition turbulator(const Field& f) {
  f.expect_object({"chamber", "walls", "height", "width", "pitch", "angle_deg", "arrangement", "end_gap", "span_margin"});
  features::TurbulatorDefinition t;
  t.chamber = f.at("chamber").integer(1, 100);
  if (f.has("walls")) {
    static const features::TurbulatorWalls walls[] = {features::TurbulatorWalls::Both, features::TurbulatorWalls::Suction,
                                                      features::TurbulatorWalls::Pressure};
    t.walls = walls[f.at("walls").choice({"both", "suction", "pressure"})];
  }
  t.height = f.at("height").number(positive(5), "mm");
  t.width = f.at("width").number(positive(10), "mm");
  t.pitch = f.at("pitch").number(positive(100), "mm");
  t.angle_deg = f.number_or("angle_deg", t.angle_deg, closed(30, 90), "deg");
  if (f.has("arrangement")) t.staggered = f.at("arrangement").choice({"inline", "staggered"}) == 1;
  t.end_gap = f.number_or("end_gap", t.end_gap, closed(0, 10), "mm");
  t.span_margin = f.number_or("span_margin", t.span_margin, closed(0, 50), "mm");
  return t;
}

features::TrailingEdgeDefinition trailing_edge(const Field& f) {
  f.expect_object({"type", "slot_height", "slot_width", "pitch", "count", "lip_thickness", "cutback_length",
                   "land_taper_deg", "span_margin", "pin_fins"});
  features::TrailingEdgeDefinition te;
  te.type = f.at("type").choice({"pressure_side_cutback", "centreline"}) == 0
                ? features::TrailingEdgeType::PressureSideCutback
                : features::TrailingEdgeType::Centreline;
  const bool cutback = te.type == features::TrailingEdgeType::PressureSideCutback;
  te.slot_height = f.at("slot_height").number(positive(10), "mm");
  te.slot_width = f.at("slot_width").number(positive(50), "mm");
  if (f.has("pitch") == f.has("count")) fail(f.path(), "give exactly one of \"pitch\" and \"count\"");
  if (f.has("pitch")) te.pitch = f.at("pitch").number(positive(100), "mm");
  if (f.has("count")) te.count = f.at("count").integer(1, 500);
  for (const char* k : {"lip_thickness", "cutback_length"})
    if (!cutback && f.has(k)) fail(f.path() + "." + k, "only for \"type\": \"pressure_side_cutback\"");
  if (cutback) {
    te.lip_thickness = f.at("lip_thickness").number(positive(10), "mm");
    te.cutback_length = f.at("cutback_length").number(positive(50), "mm");
  }
  te.land_taper_deg = f.number_or("land_taper_deg", 0, Range{0, 45, false, true}, "deg");
  te.span_margin = f.number_or("span_margin", te.span_margin, closed(0, 50), "mm");
  if (f.has("pin_fins")) {
    const Field p = f.at("pin_fins");
    p.expect_object({"diameter", "spanwise_pitch", "streamwise_pitch", "rows", "slot_gap"});
    features::PinFinDefinition pf;
    pf.diameter = p.at("diameter").number(positive(10), "mm");
    pf.spanwise_pitch = p.at("spanwise_pitch").number(positive(100), "mm");
    pf.streamwise_pitch = p.at("streamwise_pitch").number(positive(100), "mm");
    pf.rows = p.integer_or("rows", 1, 1, 20);
    pf.slot_gap = p.number_or("slot_gap", pf.slot_gap, closed(0, 20), "mm");
    te.pin_fins = pf;
  }
  return te;
}

features::CoreDefinition core(const Field& f) {
  f.expect_object({"wall_thickness", "tip_cap", "hub_floor", "ribs", "inlets", "tolerance", "turbulators",
                   "trailing_edge"});
  features::CoreDefinition c;
  c.wall_thickness = wall_thickness(f.at("wall_thickness"));
  c.tip_cap = end_wall(f.at("tip_cap"));
  c.hub_floor = end_wall(f.at("hub_floor"));
  if (f.has("ribs")) {
    const Field ribs = f.at("ribs");
    const std::size_t n = ribs.expect_array(0, 50);
    for (std::size_t i = 0; i < n; ++i) c.ribs.push_back(rib(ribs.item(i)));
  }
  if (f.has("inlets")) {
    const Field ins = f.at("inlets");
    const std::size_t n = ins.expect_array(0, 100);
    for (std::size_t i = 0; i < n; ++i) c.inlets.push_back(inlet(ins.item(i)));
  }
  c.tolerance = f.number_or("tolerance", c.tolerance, closed(1e-6, 0.1), "mm");
  if (f.has("turbulators")) {
    const Field tf = f.at("turbulators");
    const std::size_t n = tf.expect_array(0, 100);
    for (std::size_t i = 0; i < n; ++i) c.turbulators.push_back(turbulator(tf.item(i)));
  }
  if (f.has("trailing_edge")) c.trailing_edge = trailing_edge(f.at("trailing_edge"));
  return c;
}

// A table cell in mm: the whole cell must be a number ("1abc" is not 1) and finite, also once converted.
bool table_number(const std::string& cell, double mm_per_unit, double& mm) {
  std::size_t used = 0;
  try {
    mm = mm_per_unit * std::stod(cell, &used);
  } catch (const std::exception&) {  // std::invalid_argument, std::out_of_range (1e999)
    return false;
  }
  return used == cell.size() && std::isfinite(mm);
}

// A CSV/whitespace table with a header naming the columns x.., y.. and d.. (diameter), e.g. the C3X
// file "hole,U_cm,V_cm,D_cm,x_cm,y_cm"; lines starting with '#' are comments.
std::vector<features::RadialPassageDefinition> read_passage_table(const std::string& path, double mm_per_unit,
                                                                  const std::string& field) {
  std::ifstream in(path);
  if (!in) fail(field, "cannot read file " + path);
  std::string line;
  std::vector<std::string> header;
  std::vector<features::RadialPassageDefinition> out;
  int ix = -1, iy = -1, id = -1, lineno = 0;
  while (std::getline(in, line)) {
    ++lineno;
    if (line.empty() || line[0] == '#') continue;
    for (char& ch : line)
      if (ch == ',' || ch == ';' || ch == '\t') ch = ' ';
    std::istringstream s(line);
    std::vector<std::string> cells;
    for (std::string c; s >> c;) cells.push_back(c);
    if (cells.empty()) continue;
    if (header.empty()) {
      header = cells;
      for (int k = 0; k < static_cast<int>(cells.size()); ++k) {
        const char c0 = static_cast<char>(std::tolower(static_cast<unsigned char>(cells[k][0])));
        if (c0 == 'x' && ix < 0) ix = k;
        if (c0 == 'y' && iy < 0) iy = k;
        if (c0 == 'd' && id < 0) id = k;
      }
      if (ix < 0 || iy < 0 || id < 0)
        fail(field, path + " line " + std::to_string(lineno) + ": the header must name x, y and d (diameter) columns");
      continue;
    }
    const int need = std::max({ix, iy, id});
    if (static_cast<int>(cells.size()) <= need)
      fail(field, path + " line " + std::to_string(lineno) + ": expected " + std::to_string(need + 1) + " columns");
    features::RadialPassageDefinition p;
    double x = 0, y = 0, d = 0;
    if (!table_number(cells[ix], mm_per_unit, x) || !table_number(cells[iy], mm_per_unit, y) ||
        !table_number(cells[id], mm_per_unit, d))
      fail(field, path + " line " + std::to_string(lineno) + ": x, y and d must be finite numbers (also in mm), got '" +
                      cells[ix] + "', '" + cells[iy] + "', '" + cells[id] + "'");
    p.position = Eigen::Vector2d(x, y);
    p.diameter = d;
    if (!(p.diameter > 0)) fail(field, path + " line " + std::to_string(lineno) + ": the diameter must be > 0");
    out.push_back(p);
  }
  if (out.empty()) fail(field, path + ": no passages");
  return out;
}

std::vector<features::RadialPassageDefinition> radial_passages(const Field& f, const std::filesystem::path& base_dir,
                                                               std::vector<std::string>& files) {
  if (f.is_array()) {
    std::vector<features::RadialPassageDefinition> out;
    const std::size_t n = f.expect_array(1, 1000);
    for (std::size_t i = 0; i < n; ++i) {
      const Field p = f.item(i);
      p.expect_object({"position", "diameter"});
      features::RadialPassageDefinition d;
      d.position = p.at("position").pair();
      d.diameter = p.at("diameter").number(positive(100), "mm");
      out.push_back(d);
    }
    return out;
  }
  f.expect_object({"file", "unit"});
  static const char* names[] = {"mm", "cm", "m", "in"};
  static const blade::LengthUnit units[] = {blade::LengthUnit::Millimetre, blade::LengthUnit::Centimetre,
                                            blade::LengthUnit::Metre, blade::LengthUnit::Inch};
  const blade::LengthUnit unit = f.has("unit") ? units[f.at("unit").choice({names[0], names[1], names[2], names[3]})]
                                               : blade::LengthUnit::Millimetre;
  std::filesystem::path p = f.at("file").string();
  if (p.is_relative()) p = base_dir / p;
  files.push_back(p.string());
  return read_passage_table(p.string(), blade::millimetres_per(unit), f.path() + ".file");
}

}  // namespace

CoolingConfig parse_cooling(const Field& f, const std::filesystem::path& base_dir) {
  static_assert(kFilmCoolingKeys.size() == 4, "the film keys are listed here too");
  f.expect_object({"core", "radial_passages", "film_rows", "showerhead", "inserts", "film_limits"});
  CoolingConfig c;
  if (f.has("core")) c.passages.core = core(f.at("core"));
  if (f.has("radial_passages")) c.passages.radial_passages = radial_passages(f.at("radial_passages"), base_dir, c.source_files);
  c.film = parse_film_cooling(f);
  if (!c.film.empty() && !c.passages.core)
    fail(f.path(), "film rows, a showerhead and inserts need \"core\": the chambers they feed from or sit in");
  // An empty section would build an uncooled blade without a word: a cooling section must cool.
  if (c.passages.empty() && c.film.empty())
    fail(f.path(), "no cooling feature given: add \"core\" or \"radial_passages\", or leave \"cooling\" out for an uncooled blade");
  return c;
}

ConfigError cooling_error(const features::PassageInputError& e) {
  return ConfigError("cooling." + e.field() + ": " + e.what());
}

}  // namespace cg::config
