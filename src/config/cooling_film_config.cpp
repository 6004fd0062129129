#include "src/config/cooling_film_config.hpp"
#include "src/core/format.hpp"

#include <cmath>
#include <cstdio>

namespace cg::config {
namespace {

using features::FanDiffuser;
using features::HoleKind;
using features::HoleShape;

// A pitch in D: >= 1 (below the diameter the holes overlap), at most 100.
double pitch_d(const Field& f) {
  const double p = f.number(closed(-HUGE_VAL, HUGE_VAL));
  if (p < 1)
    fail(f.path(), "pitch below the diameter: must be >= 1 D (holes would overlap), got " + format_value_limit(p, 1, Allowed::above).value);
  if (p > 100) fail(f.path(), "must be <= 100 D, got " + format_value_limit(p, 100, Allowed::below).value);
  return p;
}

FanDiffuser fan(const Field& f, FanDiffuser d) {
  f.expect_object({"lateral_angle_deg", "forward_angle_deg", "diffuser_length_d", "metering_length_d", "edge_radius_d"});
  d.lateral_angle_deg = f.number_or("lateral_angle_deg", d.lateral_angle_deg, closed(0, 25), "deg");
  d.forward_angle_deg = f.number_or("forward_angle_deg", d.forward_angle_deg, closed(0, 25), "deg");
  if (f.has("diffuser_length_d") && f.has("metering_length_d"))
    fail(f.path(), "give diffuser_length_d or metering_length_d, not both (the other follows from the wall)");
  if (f.has("metering_length_d")) {
    d.metering_length_d = f.at("metering_length_d").number(open(0, 50));
    d.diffuser_length_d = 0;
  }
  if (f.has("diffuser_length_d")) {
    d.diffuser_length_d = f.at("diffuser_length_d").number(open(0, 20));
    d.metering_length_d = 0;
  }
  d.edge_radius_d = f.number_or("edge_radius_d", d.edge_radius_d, open(0, 5));
  return d;
}

void span_range(const Field& f, double& start, double& end) {
  start = f.number_or("span_start", start, closed(0, 1));
  end = f.number_or("span_end", end, closed(0, 1));
  if (end <= start) {
    const ValueLimitText t = format_value_limit(end, start, Allowed::above);
    fail(f.path() + ".span_end", "must be > span_start = " + t.limit + ", got " + t.value);
  }
}

features::FilmRowDefinition film_row(const Field& f) {
  f.expect_object({"shape", "diameter", "chord", "arc_length", "span_start", "span_end", "count", "pitch_d", "stagger",
                   "inclination_deg", "compound_deg", "chamber", "fan"});
  features::FilmRowDefinition r;
  const int shape = f.has("shape") ? f.at("shape").choice({"cylindrical", "fan_shaped", "7-7-7"}) : 0;
  r.shape.diameter = f.at("diameter").number(open(0, 5), "mm");
  if (shape == 0) {
    if (f.has("fan")) fail(f.path() + ".fan", "only for shape \"fan_shaped\" or \"7-7-7\"");
  } else {
    r.shape = features::preset_777(r.shape.diameter);
    if (f.has("fan")) r.shape.fan = fan(f.at("fan"), r.shape.fan);
    if (shape == 2) r.inclination_deg = 30;  // the preset's inclination unless given
  }
  if (f.has("chord") == f.has("arc_length")) fail(f.path(), "give exactly one of chord and arc_length");
  if (f.has("chord")) r.position = {features::RowPosition::Kind::Chord, f.at("chord").number(open(-1, 1))};
  else r.position = {features::RowPosition::Kind::ArcLength, f.at("arc_length").number(closed(-1000, 1000), "mm")};
  span_range(f, r.span_start, r.span_end);
  if (f.has("count") == f.has("pitch_d") && !(shape == 2 && !f.has("count")))
    fail(f.path(), "give exactly one of count and pitch_d");
  if (f.has("count")) r.count = f.at("count").integer(1, 10000);
  else r.pitch_d = f.has("pitch_d") ? pitch_d(f.at("pitch_d")) : 6;  // 7-7-7: P/D 6
  r.stagger = f.number_or("stagger", 0, Range{0, 1, false, true});
  r.inclination_deg = f.number_or("inclination_deg", r.inclination_deg, Range{0, 90, true, false}, "deg");
  r.compound_deg = f.number_or("compound_deg", 0, closed(-90, 90), "deg");
  r.chamber = f.integer_or("chamber", 0, 1, 100);
  return r;
}

features::ShowerheadDefinition showerhead(const Field& f) {
  f.expect_object({"rows", "diameter", "row_spacing_d", "pitch_d", "stagnation_arc_length", "radial_angle_deg", "toward",
                   "span_start", "span_end", "chamber"});
  features::ShowerheadDefinition s;
  s.rows = f.integer_or("rows", s.rows, 1, 15);
  s.diameter = f.at("diameter").number(open(0, 5), "mm");
  if (f.has("row_spacing_d")) {
    s.row_spacing_d = f.at("row_spacing_d").number(closed(-HUGE_VAL, HUGE_VAL));
    if (s.row_spacing_d < 1 || s.row_spacing_d > 20)
      fail(f.path() + ".row_spacing_d", "must be in [1, 20] D (below 1 D the rows overlap), got " + format_value_range(s.row_spacing_d, 1, 20).value);
  }
  if (f.has("pitch_d")) s.pitch_d = pitch_d(f.at("pitch_d"));
  s.stagnation_arc = f.number_or("stagnation_arc_length", 0, closed(-50, 50), "mm");
  s.radial_angle_deg = f.number_or("radial_angle_deg", s.radial_angle_deg, Range{0, 90, true, false}, "deg");
  if (f.has("toward")) s.toward_tip = f.at("toward").choice({"tip", "hub"}) == 0;
  span_range(f, s.span_start, s.span_end);
  s.chamber = f.integer_or("chamber", 0, 1, 100);
  return s;
}

features::InsertDefinition insert(const Field& f) {
  f.expect_object({"chamber", "gap", "sheet_thickness", "hub_gap", "tip_gap", "hub_end", "tip_end", "jets"});
  features::InsertDefinition d;
  d.chamber = f.at("chamber").integer(1, 100);
  d.gap = f.at("gap").number(Range{0, 10, true, false}, "mm");
  d.sheet_thickness = f.at("sheet_thickness").number(Range{0, 5, true, false}, "mm");
  if (f.has("hub_gap")) d.hub_gap = f.at("hub_gap").number(closed(0, 50), "mm");
  if (f.has("tip_gap")) d.tip_gap = f.at("tip_gap").number(closed(0, 50), "mm");
  if (f.has("hub_end")) d.hub_open = f.at("hub_end").choice({"open", "closed"}) == 0;
  if (f.has("tip_end")) d.tip_open = f.at("tip_end").choice({"open", "closed"}) == 0;
  const Field j = f.at("jets");
  j.expect_object({"diameter", "spacing_x_d", "spacing_y_d", "pattern", "margin"});
  d.jet_diameter = j.at("diameter").number(Range{0, 5, true, false}, "mm");
  d.jet_spacing_x_d = j.number_or("spacing_x_d", d.jet_spacing_x_d, closed(2, 100));
  d.jet_spacing_y_d = j.number_or("spacing_y_d", d.jet_spacing_y_d, closed(2, 100));
  if (j.has("pattern")) d.staggered = j.at("pattern").choice({"staggered", "inline"}) == 0;
  d.jet_margin = j.number_or("margin", d.jet_margin, closed(0, 20), "mm");
  return d;
}

}  // namespace

features::FilmCoolingDefinition parse_film_cooling(const Field& c) {
  features::FilmCoolingDefinition d;
  if (c.has("film_rows")) {
    const Field rows = c.at("film_rows");
    const std::size_t n = rows.expect_array(1, 200);
    for (std::size_t i = 0; i < n; ++i) d.rows.push_back(film_row(rows.item(i)));
  }
  if (c.has("showerhead")) d.showerhead = showerhead(c.at("showerhead"));
  if (c.has("inserts")) {
    const Field ins = c.at("inserts");
    const std::size_t n = ins.expect_array(1, 50);
    for (std::size_t i = 0; i < n; ++i) d.inserts.push_back(insert(ins.item(i)));
  }
  if (c.has("film_limits")) {
    const Field l = c.at("film_limits");
    l.expect_object({"min_ligament", "clearance"});
    d.limits.min_ligament = l.number_or("min_ligament", d.limits.min_ligament, closed(0, 10), "mm");
    d.limits.clearance = l.number_or("clearance", d.limits.clearance, closed(0.01, 2), "mm");
  }
  return d;
}

ConfigError film_error(const features::FilmInputError& e) { return ConfigError("cooling." + e.field() + ": " + e.what()); }

}  // namespace cg::config
