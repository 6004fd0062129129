#include "src/network/network_graph.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <set>

#include <BRepAdaptor_Surface.hxx>
#include <BRepBndLib.hxx>
#include <BRepTools.hxx>
#include <Bnd_Box.hxx>

#include "features/passages/section_surface.hpp"
#include "src/blade/blade_coordinates.hpp"
#include "src/core/constants.hpp"
#include "src/network/ccx_connectivity.hpp"
#include "src/network/network_correlations.hpp"
#include "src/network/network_sections.hpp"

namespace cg::network {
namespace {

using Vec3 = Eigen::Vector3d;
using features::SpanEnd;
using Sections = std::map<std::string, std::vector<features::CrossSection>>;

// End stations are cut this far inside the end wall or open end (mm): on the end face itself a section
// would be ill-defined, and the piece between is negligible (1e-4 of a 76 mm span).
constexpr double kEndOffsetMm = 0.01;
// A chamber (or radial passage) has at least this many segments carrying flow (issue: >= 9 per chamber).
constexpr int kMinSegments = 9;

// One station of a passage: a section measured on the built part, or the passage's end (end wall or open
// end), measured kEndOffsetMm inside it.
struct Station {
  double span = 0, area = 0, perimeter = 0;
  bool end = false;       ///< at an end wall or open end
  bool measured = false;  ///< false: no section of this passage there, the nearest measured section's area
  Vec3 point = Vec3::Zero();  ///< on the passage's mid line
  int node = 0;
};

struct Passage {
  std::string name;
  int number = 0;       ///< chamber number (1-based) or radial passage number
  bool chamber = true;  ///< false: a radial passage
  std::vector<Station> stations;  ///< hub -> tip
  int feed = -1;        ///< index of the station the coolant enters at (-1: not fed yet)
  bool hub_turn = false, tip_turn = false;  ///< the end is a turnaround
  std::vector<int> segment_elements;        ///< hub -> tip, one per station pair
};

// Equivalent rectangle with the same area and wetted perimeter: W / H >= 1 (NaN when none exists).
double aspect_ratio(double a, double p) {
  const double half = p / 2, disc = half * half - 4 * a;
  if (!(disc >= 0)) return kUnset;
  const double w = (half + std::sqrt(disc)) / 2, h = half - w;
  return h > 0 ? w / h : kUnset;
}

// An element from station a to station b of a passage: its nodes, end areas, perimeters, the mean D_h
// and the aspect ratio of the mean section.
void join_stations(Element& e, const Station& a, const Station& b) {
  e.upstream = a.node;
  e.downstream = b.node;
  e.area_in = a.area;
  e.area_out = b.area;
  e.perimeter_in = a.perimeter;
  e.perimeter_out = b.perimeter;
  e.hydraulic_diameter = 0.5 * (4 * a.area / a.perimeter + 4 * b.area / b.perimeter);
  e.aspect_ratio = aspect_ratio(0.5 * (a.area + b.area), 0.5 * (a.perimeter + b.perimeter));
}

class Builder {
 public:
  /// `cuts`: sections of the passages measured on the built part (measure_stations) at the passage
  /// report's spans, the end stations' (station_spans) and `extra` spans per passage.
  Builder(const NetworkInput& in, const Sections& cuts, const std::map<std::string, std::vector<double>>& extra)
      : in_(in), c_(*in.config), bc_(*in.config->coolant), coords_(std::make_unique<blade::BladeCoordinates>(*in.model)),
        cuts_(cuts), extra_(extra) {}

  Network run();

 private:
  int add_node(Node n) {
    n.id = static_cast<int>(net_.nodes.size()) + 1;
    net_.nodes.push_back(std::move(n));
    return net_.nodes.back().id;
  }
  Element& add_element(Element e) {
    e.id = static_cast<int>(net_.elements.size()) + 1;
    net_.elements.push_back(std::move(e));
    return net_.elements.back();
  }
  Vec3 mid_point(const Passage& p, double span) const;
  double radius(const Vec3& p) const { return rotor_ ? std::hypot(p.y(), p.z()) : kUnset; }
  void gas();
  void passages();
  void orient();
  void stations_to_nodes(Passage& p);
  void segments(Passage& p);
  void inlets();
  void bends();
  void inserts();
  void holes();
  void slots();
  double compound_angle(const features::HoleMeasure& h) const;
  void prune_dead_ends();
  int pin_bank_element(const features::PinFinDefinition& def, int pins, double pin_length, std::size_t slots, const Passage& p,
                       const std::string& slot, double span, int station);
  int sink(config::SinkKind kind, const std::string& row = "");
  Passage* find(const std::string& name) {
    for (Passage& p : passages_)
      if (p.name == name) return &p;
    return nullptr;
  }
  int nearest_station(const Passage& p, double span) const {
    int best = 0;
    for (std::size_t i = 1; i < p.stations.size(); ++i)
      if (std::abs(p.stations[i].span - span) < std::abs(p.stations[static_cast<std::size_t>(best)].span - span)) best = static_cast<int>(i);
    return best;
  }
  std::string segment_at(const Passage& p, double span) const;

  const NetworkInput& in_;
  const config::Config& c_;
  const config::CoolantConfig& bc_;
  std::unique_ptr<blade::BladeCoordinates> coords_;
  const Sections& cuts_;
  const std::map<std::string, std::vector<double>>& extra_;
  bool rotor_ = false;
  Network net_;
  std::vector<Passage> passages_;
  int supply_ = 0;
  std::map<std::string, int> sinks_;  ///< by node name
};

const features::CoreDefinition* core_of(const config::Config& c) {
  return c.cooling.passages.core ? &*c.cooling.passages.core : nullptr;
}

Vec3 Builder::mid_point(const Passage& p, double span) const {
  if (!p.chamber) {
    const auto& def = c_.cooling.passages.radial_passages.at(static_cast<std::size_t>(p.number - 1));
    const features::SpanSurface s = features::span_surfaces(*in_.model, {span}).front();
    return {def.position.x(), def.position.y(), s.origin.z()};
  }
  const features::CoreDefinition& cd = *core_of(c_);
  const std::size_t k = static_cast<std::size_t>(p.number);
  const double s0 = k == 1 ? 0 : cd.ribs[k - 2].suction_chord, s1 = k > cd.ribs.size() ? 1 : cd.ribs[k - 1].suction_chord;
  const double p0 = k == 1 ? 0 : cd.ribs[k - 2].pressure_chord, p1 = k > cd.ribs.size() ? -1 : cd.ribs[k - 1].pressure_chord;
  return 0.5 * (coords_->frame(span, 0.5 * (s0 + s1)).point + coords_->frame(span, 0.5 * (p0 + p1)).point);
}

void Builder::gas() {
  net_.gas.gas_constant = bc_.gas_constant;
  net_.gas.cp = bc_.cp > 0 ? bc_.cp : air_cp(bc_.supply_total_temperature);
  net_.gas.viscosity = bc_.viscosity > 0 ? bc_.viscosity : air_viscosity(bc_.supply_total_temperature);
  rotor_ = in_.model->net.has_value();
  net_.omega = rotor_ ? bc_.rotational_speed_rpm * 2 * kPi / 60 : 0;
  if (!rotor_ && bc_.rotational_speed_rpm > 0)
    net_.notes.push_back("coolant.rotational_speed_rpm ignored: a straight vane does not rotate");
}

// The spans of the end stations: kEndOffsetMm inside the hub and tip ends (end wall or open end).
std::pair<double, double> end_station_spans(const NetworkInput& in) {
  const features::CoreDefinition* cd = core_of(*in.config);
  const double len = in.model->span_length, eps = kEndOffsetMm / len;
  const double hub = cd && !cd->hub_floor.open ? cd->hub_floor.thickness / len : 0.0;
  const double tip = cd && !cd->tip_cap.open ? 1 - cd->tip_cap.thickness / len : 1.0;
  return {hub + eps, tip - eps};
}

// The passages with their stations hub -> tip: the passage report's span sections and any extra spans,
// measured on the built part (cuts_), and an end station where the passage ends at an end wall or an
// open end (not at a turnaround: the bend starts at the last section).
void Builder::passages() {
  const features::CoreDefinition* cd = core_of(c_);
  const auto [hub, tip] = end_station_spans(in_);
  for (const features::PassageMeasure& m : in_.passages->passages) {
    Passage p;
    p.name = m.name;
    p.chamber = m.name.rfind("chamber_", 0) == 0;
    p.number = std::stoi(m.name.substr(m.name.rfind('_') + 1));
    std::vector<features::CrossSection> report = m.sections;
    std::sort(report.begin(), report.end(), [](const auto& a, const auto& b) { return a.span < b.span; });
    if (report.size() < 2) throw NetworkError(m.name + ": fewer than 2 measured sections, no network segments");
    if (p.chamber && cd) {
      const std::size_t k = static_cast<std::size_t>(p.number);
      for (std::size_t r : {k - 1, k - 2})
        if (r < cd->ribs.size() && cd->ribs[r].turnaround)
          (cd->ribs[r].turnaround->end == SpanEnd::Hub ? p.hub_turn : p.tip_turn) = true;
    }
    const auto cut = cuts_.find(m.name);
    // The section at `span`: measured on the built part, else the report's there (the cooled blade before
    // its holes), else (ends) the nearest report section's area.
    const auto station = [&](double span, bool end) -> std::optional<Station> {
      if (cut != cuts_.end())
        for (const auto& s : cut->second)
          if (std::abs(s.span - span) < 1e-12) return Station{span, s.area, s.wetted_perimeter, end, true};
      for (const auto& s : report)
        if (std::abs(s.span - span) < 1e-12) return Station{span, s.area, s.wetted_perimeter, end, true};
      if (!end) return std::nullopt;
      const auto& near = std::abs(report.front().span - span) < std::abs(report.back().span - span) ? report.front() : report.back();
      return Station{span, near.area, near.wetted_perimeter, end, false};
    };
    std::vector<double> spans;
    for (const auto& s : report) spans.push_back(s.span);
    if (const auto it = extra_.find(m.name); it != extra_.end()) spans.insert(spans.end(), it->second.begin(), it->second.end());
    std::sort(spans.begin(), spans.end());
    if (!p.hub_turn) p.stations.push_back(*station(hub, true));
    for (double span : spans)
      if (const auto st = station(span, false)) p.stations.push_back(*st);
    if (!p.tip_turn) p.stations.push_back(*station(tip, true));
    for (Station& st : p.stations) st.point = mid_point(p, st.span);
    passages_.push_back(std::move(p));
  }
  if (passages_.empty()) throw NetworkError("the part has no measured coolant passage");
}

// Which end each passage is fed at: inlets and open ends first, then through turnarounds.
void Builder::orient() {
  const features::CoreDefinition* cd = core_of(c_);
  for (Passage& p : passages_) {
    if (!p.chamber) p.feed = 0;  // radial passages: from the hub
    if (cd && p.chamber) {
      for (const auto& inl : cd->inlets)
        if (inl.chamber == p.number) p.feed = inl.end == SpanEnd::Hub ? 0 : static_cast<int>(p.stations.size()) - 1;
      if (p.feed < 0 && cd->hub_floor.open) p.feed = 0;
      if (p.feed < 0 && cd->tip_cap.open) p.feed = static_cast<int>(p.stations.size()) - 1;
    }
  }
  // Through turnarounds: the chamber joined at the end a fed chamber's flow arrives at.
  for (bool changed = true; changed;) {
    changed = false;
    if (!cd) break;
    for (std::size_t r = 0; r < cd->ribs.size(); ++r) {
      if (!cd->ribs[r].turnaround) continue;
      Passage *a = find("chamber_" + std::to_string(r + 1)), *b = find("chamber_" + std::to_string(r + 2));
      if (!a || !b) continue;
      const bool at_hub = cd->ribs[r].turnaround->end == SpanEnd::Hub;
      for (auto [up, down] : {std::pair{a, b}, std::pair{b, a}}) {
        const int arrive = up->feed == 0 ? static_cast<int>(up->stations.size()) - 1 : 0;
        if (up->feed < 0 || down->feed >= 0 || (arrive == 0) != at_hub) continue;
        down->feed = at_hub ? 0 : static_cast<int>(down->stations.size()) - 1;
        changed = true;
      }
    }
  }
  for (const Passage& p : passages_)
    if (p.feed < 0) throw NetworkError(p.name + ": no inlet, open end or turnaround from a fed chamber feeds it");
}

std::string Builder::segment_at(const Passage& p, double span) const {
  for (std::size_t i = 0; i + 1 < p.stations.size(); ++i)
    if (span <= p.stations[i + 1].span || i + 2 == p.stations.size())
      return net_.elements.at(static_cast<std::size_t>(p.segment_elements[i] - 1)).name;
  return "";
}

char station_label(std::size_t i) { return static_cast<char>('0' + i % 10); }

void Builder::stations_to_nodes(Passage& p) {
  const features::CoreDefinition* cd = core_of(c_);
  for (std::size_t i = 0; i < p.stations.size(); ++i) {
    Station& st = p.stations[i];
    const bool hub_end = i == 0 && !p.hub_turn, tip_end = i + 1 == p.stations.size() && !p.tip_turn;
    const bool hub_open = !p.chamber || (cd && cd->hub_floor.open), tip_open = !p.chamber || (cd && cd->tip_cap.open);
    // An open end the coolant enters at is the supply; one it leaves through is the tip sink (an open
    // hub too: the sinks have no hub kind, noted).
    const int last = static_cast<int>(p.stations.size()) - 1;
    if ((hub_end && hub_open) || (tip_end && tip_open)) {
      const bool entry = hub_end ? p.feed == 0 : p.feed == last;
      st.node = entry ? supply_ : sink(config::SinkKind::Tip);
      if (!entry && hub_end) net_.notes.push_back(p.name + " leaves through the open hub at coolant.sinks.tip_pa");
      continue;
    }
    Node n;
    n.name = p.name + "_s" + std::string(1, station_label(i / 10)) + station_label(i);
    n.chamber = p.name;
    n.span = st.span;
    n.radius = radius(st.point);
    st.node = add_node(n);
  }
}

void Builder::segments(Passage& p) {
  const features::TurbulatorDefinition* turb = nullptr;
  if (const auto* cd = core_of(c_); cd && p.chamber)
    for (const auto& t : cd->turbulators)
      if (t.chamber == p.number) turb = &t;
  for (std::size_t i = 0; i + 1 < p.stations.size(); ++i) {
    // Along the flow: away from the feed station.
    const bool up_hub = static_cast<int>(i) >= p.feed;
    const Station& a = p.stations[up_hub ? i : i + 1];
    const Station& b = p.stations[up_hub ? i + 1 : i];
    Element e;
    e.name = p.name + "_seg_" + std::string(1, station_label(i / 10)) + station_label(i);
    e.kind = ElementKind::Segment;
    e.chamber = p.name;
    join_stations(e, a, b);
    e.length = (b.point - a.point).norm();
    e.span_in = a.span;
    e.span_out = b.span;
    e.radius_in = radius(a.point);
    e.radius_out = radius(b.point);
    e.faces = {p.chamber ? p.name + "_wall" : p.name};
    if (turb && !a.end && !b.end) {
      e.turbulators = turbulation(*turb, e.hydraulic_diameter, e.aspect_ratio, e.length);
      e.roughness = equivalent_roughness(*e.turbulators, e.hydraulic_diameter);
      e.faces.push_back("turbulator_*");
    }
    if (net_.omega > 0 && e.upstream != supply_) {
      // Fanno pipe to a node at the downstream radius, then the forced vortex (centrifugal pumping).
      Node n;
      n.name = net_.node(b.node).name + "_pipe";
      n.chamber = p.name;
      n.span = b.span;
      n.radius = e.radius_in;
      const int mid = add_node(n);
      Element rot;
      rot.name = p.name + "_rot_" + std::string(1, station_label(i / 10)) + station_label(i);
      rot.kind = ElementKind::Rotation;
      rot.chamber = p.name;
      rot.upstream = mid;
      rot.downstream = b.node;
      rot.radius_in = e.radius_in;
      rot.radius_out = e.radius_out;
      rot.span_in = a.span;
      rot.span_out = b.span;
      e.downstream = mid;
      p.segment_elements.push_back(add_element(e).id);
      add_element(rot);
    } else {
      p.segment_elements.push_back(add_element(e).id);
    }
  }
}

// The sink node of an exit of `kind` in `row`: the row's own (coolant.sinks.rows) or its kind's.
int Builder::sink(config::SinkKind kind, const std::string& row) {
  const bool own = bc_.sink_by_row.count(row) > 0;
  std::string name = std::string("sink_") + config::CoolantConfig::sink_field(kind);
  name = own ? "sink_" + row : name.substr(0, name.size() - 3);  // without "_pa"
  const auto it = sinks_.find(name);
  if (it != sinks_.end()) return it->second;
  Node n;
  n.name = name;
  n.kind = NodeKind::Sink;
  n.pressure = bc_.sink(row, kind);
  n.temperature = bc_.supply_total_temperature;
  return sinks_[name] = add_node(n);
}

void Builder::inlets() {
  const features::CoreDefinition* cd = core_of(c_);
  if (!cd) return;
  for (std::size_t m = 0; m < cd->inlets.size(); ++m) {
    const auto& inl = cd->inlets[m];
    Passage* p = find("chamber_" + std::to_string(inl.chamber));
    if (!p) continue;
    const Station& st = inl.end == SpanEnd::Hub ? p->stations.front() : p->stations.back();
    Element e;
    e.name = "inlet_" + std::to_string(m + 1);
    e.kind = ElementKind::Inlet;
    e.chamber = p->name;
    e.upstream = supply_;
    e.downstream = st.node;
    Opening o;
    o.row = e.name;
    o.shape = "cylindrical";
    o.diameter = inl.diameter;
    o.metering_length = inl.end == SpanEnd::Hub ? cd->hub_floor.thickness : cd->tip_cap.thickness;
    o.length_d = o.metering_length / o.diameter;
    o.metering_area = o.exit_area = kPi * inl.diameter * inl.diameter / 4;
    e.opening = o;
    e.length = o.metering_length;
    e.area_in = e.area_out = o.metering_area;
    e.hydraulic_diameter = inl.diameter;
    e.radius_in = e.radius_out = radius(st.point);
    e.span_in = e.span_out = st.span;
    e.faces = {e.name};
    add_element(e);
  }
}

void Builder::bends() {
  const features::CoreDefinition* cd = core_of(c_);
  if (!cd) return;
  int n = 0;
  for (std::size_t r = 0; r < cd->ribs.size(); ++r) {
    if (!cd->ribs[r].turnaround) continue;
    ++n;
    Passage *a = find("chamber_" + std::to_string(r + 1)), *b = find("chamber_" + std::to_string(r + 2));
    if (!a || !b) continue;
    const bool at_hub = cd->ribs[r].turnaround->end == SpanEnd::Hub;
    // Upstream: the chamber whose flow arrives at this end.
    const bool a_up = (a->feed == 0) != at_hub;
    Passage& up = a_up ? *a : *b;
    Passage& down = a_up ? *b : *a;
    const Station& s0 = at_hub ? up.stations.front() : up.stations.back();
    const Station& s1 = at_hub ? down.stations.front() : down.stations.back();
    Element e;
    e.name = "turnaround_" + std::to_string(n);
    e.kind = ElementKind::Bend;
    e.chamber = up.name;
    join_stations(e, s0, s1);
    e.bend_angle_deg = 180;
    e.bend_radius = 0.5 * (s1.point - s0.point).norm();
    // The turn's flow area: the gap between the rib tip and the end wall times the cavity's depth at the
    // rib (its outer-wall points at the rib's chords less the wall on both sides), when less than the
    // chambers' areas: a narrow gap is the bend's throat.
    const features::RibDefinition& rib = cd->ribs[r];
    const double gap = rib.turnaround->gap, len = in_.model->span_length;
    const double span = at_hub ? cd->hub_floor.thickness / len + 0.5 * gap / len : 1 - cd->tip_cap.thickness / len - 0.5 * gap / len;
    const double depth = (coords_->frame(span, rib.suction_chord).point - coords_->frame(span, rib.pressure_chord).point).norm() -
                         cd->wall_thickness.at(span, rib.suction_chord) - cd->wall_thickness.at(span, rib.pressure_chord);
    e.bend_gap = gap;
    e.bend_depth = depth;
    if (depth > 0 && gap * depth < std::min(e.area_in, e.area_out)) {
      e.area_in = e.area_out = gap * depth;
      e.hydraulic_diameter = 2 * gap * depth / (gap + depth);
    }
    e.length = kPi * e.bend_radius;
    e.span_in = s0.span;
    e.span_out = s1.span;
    e.radius_in = radius(s0.point);
    e.radius_out = radius(s1.point);
    e.faces = {"rib_" + std::to_string(r + 1), e.name, up.name + "_wall", down.name + "_wall"};
    add_element(e);
  }
}

// An insert's interior is a plenum between the chamber's inlets and its jets; the jets (one element,
// every jet hole of the insert) feed the chamber's middle station.
void Builder::inserts() {
  if (!in_.film) return;
  for (const features::InsertMeasure& im : in_.film->inserts) {
    Passage* p = find(im.chamber);
    if (!p || im.jet_holes <= 0) continue;
    Node n;
    n.name = im.name + "_inside";
    n.chamber = p->name;
    const int inside = add_node(n);
    // The chamber's inlets feed the insert instead.
    for (Element& e : net_.elements)
      if (e.kind == ElementKind::Inlet && e.chamber == p->name) e.downstream = inside;
    const std::size_t mid = p->stations.size() / 2;
    Element e;
    e.name = im.name + "_jets";
    e.kind = ElementKind::Jets;
    e.chamber = p->name;
    e.upstream = inside;
    e.downstream = p->stations[mid].node;
    Opening o;
    o.row = im.name;
    o.shape = "cylindrical";
    o.count = im.jet_holes;
    o.metering_area = o.exit_area = im.jet_area;
    o.diameter = std::sqrt(4 * im.jet_area / im.jet_holes / kPi);
    o.metering_length = im.sheet_thickness;
    o.length_d = o.metering_length / o.diameter;
    o.z_d = im.gap / o.diameter;
    for (const auto& d : c_.cooling.film.inserts)
      if ("chamber_" + std::to_string(d.chamber) == p->name) {
        o.x_d = d.jet_spacing_x_d;
        o.y_d = d.jet_spacing_y_d;
      }
    e.opening = o;
    e.length = o.metering_length;
    e.area_in = e.area_out = im.jet_area;
    e.hydraulic_diameter = o.diameter;
    e.span_in = e.span_out = p->stations[mid].span;
    e.faces = {im.name};
    add_element(e);
  }
}

// One element per film and showerhead hole, from the station nearest its inlet (on the cavity wall) to
// the sink of its kind.
void Builder::holes() {
  if (!in_.film) return;
  for (std::size_t k = 0; k < in_.film->holes.size(); ++k) {
    const features::HoleMeasure& h = in_.film->holes[k];
    Passage* p = find(h.chamber);
    if (!p) throw NetworkError(h.name + ": its chamber \"" + h.chamber + "\" has no measured sections");
    const Vec3 exit(h.exit[0], h.exit[1], h.exit[2]), axis(h.axis[0], h.axis[1], h.axis[2]);
    const Vec3 inlet = exit + h.length * axis;
    const blade::BladeLocateResult loc = coords_->locate(inlet);
    const double span = loc.found ? loc.coordinate.span : h.span;
    const bool shower = h.row.rfind("showerhead", 0) == 0;
    const config::SinkKind kind = shower ? config::SinkKind::Showerhead
                                         : (h.chord > 0 ? config::SinkKind::SuctionSide : config::SinkKind::PressureSide);
    const Station& st = p->stations[static_cast<std::size_t>(nearest_station(*p, span))];
    Element e;
    e.name = h.name;
    e.kind = ElementKind::FilmHole;
    e.chamber = p->name;
    e.enters_from = segment_at(*p, span);
    e.upstream = st.node;
    e.downstream = sink(kind, h.row);
    Opening o;
    o.row = h.row;
    o.shape = h.shape;
    o.diameter = h.diameter;
    o.metering_length = h.metering_length;
    o.length_d = h.metering_length_d;
    o.inclination_deg = h.inclination_deg;
    o.compound_deg = compound_angle(h);
    o.metering_area = h.metering_area;
    o.exit_area = h.exit_area;
    o.area_ratio = h.area_ratio;
    o.sink = net_.node(e.downstream).name.substr(5);
    o.hole_index = static_cast<int>(k);
    e.opening = o;
    e.length = h.length;
    e.area_in = h.metering_area;
    e.area_out = h.exit_area;
    e.hydraulic_diameter = h.diameter;
    e.span_in = span;
    e.span_out = h.span;
    e.radius_in = radius(inlet);
    e.radius_out = radius(exit);
    e.faces = {h.name};
    add_element(e);
  }
}

double Builder::compound_angle(const features::HoleMeasure& h) const {
  const std::string prefix = "film_row_";
  if (h.row.rfind(prefix, 0) == 0) {
    const std::size_t k = static_cast<std::size_t>(std::stoi(h.row.substr(prefix.size())));
    if (k >= 1 && k <= c_.cooling.film.rows.size()) return c_.cooling.film.rows[k - 1].compound_deg;
  }
  if (h.row.rfind("showerhead", 0) == 0 && c_.cooling.film.showerhead)
    return c_.cooling.film.showerhead->toward_tip ? 90 : -90;  // the axis leans along the span
  return kUnset;
}

// The pins' mean length across the chamber: the axial extent (v range) of each pin_fin_<nnn>'s
// cylindrical faces on the part. Returns {pins, mean length}.
std::pair<int, double> pin_lengths(const brep::NamedShape& blade) {
  std::map<std::string, std::pair<double, double>> range;
  for (const brep::NamedFace& f : blade.faces) {
    if (f.name.rfind("pin_fin_", 0) != 0 || BRepAdaptor_Surface(f.face).GetType() != GeomAbs_Cylinder) continue;
    double u0, u1, v0, v1;
    BRepTools::UVBounds(f.face, u0, u1, v0, v1);
    const auto it = range.find(f.name);
    range[f.name] = it == range.end() ? std::pair{v0, v1} : std::pair{std::min(v0, it->second.first), std::max(v1, it->second.second)};
  }
  double sum = 0;
  for (const auto& [name, r] : range) sum += r.second - r.first;
  return {static_cast<int>(range.size()), range.empty() ? 0.0 : sum / static_cast<double>(range.size())};
}

// Trailing-edge slots: one element per slot (faces te_slot_<nn> on the blade), from the last chamber's
// station nearest the slot's span to the trailing-edge sink; with pin fins, the slot's share of the pin
// bank in front of it as an element of its own (station -> pin bank -> slot).
void Builder::slots() {
  const features::CoreDefinition* cd = core_of(c_);
  if (!cd || !cd->trailing_edge || in_.part->empty()) return;
  const features::TrailingEdgeDefinition& te = *cd->trailing_edge;
  Passage* p = find("chamber_" + std::to_string(cd->ribs.size() + 1));
  if (!p) return;
  std::map<std::string, Bnd_Box> boxes;
  for (const brep::NamedFace& f : in_.part->front().geometry.faces)
    if (f.name.rfind("te_slot_", 0) == 0) BRepBndLib::Add(f.face, boxes[f.name]);
  const auto [pins, pin_length] = pin_lengths(in_.part->front().geometry);
  for (const auto& [name, box] : boxes) {
    double x0, y0, z0, x1, y1, z1;
    box.Get(x0, y0, z0, x1, y1, z1);
    const blade::BladeLocateResult loc = coords_->locate(Vec3(0.5 * (x0 + x1), 0.5 * (y0 + y1), 0.5 * (z0 + z1)));
    const double span = loc.found ? loc.coordinate.span : 0.5;
    const Station& st = p->stations[static_cast<std::size_t>(nearest_station(*p, span))];
    int from = st.node;
    if (te.pin_fins && pins > 0) from = pin_bank_element(*te.pin_fins, pins, pin_length, boxes.size(), *p, name, span, st.node);
    Element e;
    e.name = name;
    e.kind = ElementKind::Slot;
    e.chamber = p->name;
    e.enters_from = segment_at(*p, span);
    e.upstream = from;
    e.downstream = sink(config::SinkKind::TrailingEdge, "te_slots");
    Opening o;
    o.row = "te_slots";
    o.shape = "slot";
    o.metering_area = o.exit_area = te.slot_height * te.slot_width;
    o.diameter = 2 * te.slot_height * te.slot_width / (te.slot_height + te.slot_width);
    o.sink = net_.node(e.downstream).name.substr(5);
    e.opening = o;
    e.area_in = e.area_out = o.metering_area;
    e.hydraulic_diameter = o.diameter;
    e.span_in = e.span_out = span;
    e.faces = {name};
    add_element(e);
  }
}

// The pin bank in front of slot `slot`: its share of the bank's minimum gap ((S - D) x pin length per pin
// of a row, over the slots), the gap's hydraulic diameter and the rows' depth, from the station to a
// node of its own at the slot's inlet. Returns that node.
int Builder::pin_bank_element(const features::PinFinDefinition& def, int pins, double pin_length, std::size_t slots,
                              const Passage& p, const std::string& slot, double span, int station) {
  PinBank bank = pin_bank(def, pins);
  bank.height = pin_length;
  const double gap = def.spanwise_pitch - def.diameter;
  bank.gap_area = gap * pin_length * pins / std::max(bank.rows, 1) / static_cast<double>(slots);
  Node n;
  n.name = slot + "_inlet";
  n.chamber = p.name;
  n.span = span;
  Element e;
  e.name = slot + "_pins";
  e.kind = ElementKind::PinBank;
  e.chamber = p.name;
  e.enters_from = segment_at(p, span);
  e.upstream = station;
  e.downstream = add_node(n);
  e.area_in = e.area_out = bank.gap_area;
  e.hydraulic_diameter = 2 * gap * pin_length / (gap + pin_length);
  e.length = bank.rows * def.streamwise_pitch;
  e.span_in = e.span_out = span;
  e.pins = bank;
  e.faces = {"pin_fin_*"};
  add_element(e);
  return e.downstream;
}

// A closed end beyond the last hole carries no flow (and CalculiX refuses a node with one element):
// junctions with a single element are removed with it, repeatedly; ids are renumbered.
void Builder::prune_dead_ends() {
  for (bool removed = true; removed;) {
    removed = false;
    std::vector<int> degree(net_.nodes.size() + 1, 0);
    for (const Element& e : net_.elements) ++degree[static_cast<std::size_t>(e.upstream)], ++degree[static_cast<std::size_t>(e.downstream)];
    std::vector<int> node_id(net_.nodes.size() + 1, 0);
    std::vector<Node> nodes;
    for (Node& n : net_.nodes)
      if (n.kind != NodeKind::Junction || degree[static_cast<std::size_t>(n.id)] > 1) {
        node_id[static_cast<std::size_t>(n.id)] = static_cast<int>(nodes.size()) + 1;
        nodes.push_back(n);
        nodes.back().id = static_cast<int>(nodes.size());
      } else {
        removed = true;
      }
    std::vector<Element> elements;
    for (Element& e : net_.elements) {
      const int u = node_id[static_cast<std::size_t>(e.upstream)], d = node_id[static_cast<std::size_t>(e.downstream)];
      if (!u || !d) continue;
      e.upstream = u;
      e.downstream = d;
      e.id = static_cast<int>(elements.size()) + 1;
      elements.push_back(e);
    }
    net_.nodes = std::move(nodes);
    net_.elements = std::move(elements);
  }
}

Network Builder::run() {
  gas();
  Node s;
  s.name = "supply";
  s.kind = NodeKind::Supply;
  s.pressure = bc_.supply_total_pressure;
  s.temperature = bc_.supply_total_temperature;
  supply_ = add_node(s);
  passages();
  orient();
  if (in_.film)  // a chamber with an insert is fed by the jets at its middle station
    for (const features::InsertMeasure& im : in_.film->inserts)
      if (Passage* p = find(im.chamber); p && im.jet_holes > 0) p->feed = static_cast<int>(p->stations.size() / 2);
  for (Passage& p : passages_) {
    stations_to_nodes(p);
    segments(p);
  }
  inlets();
  inserts();
  bends();
  holes();
  slots();
  prune_dead_ends();
  if (!number_nodes_for_ccx(net_))
    net_.notes.push_back("no node numbering tried passes CalculiX 2.20's connectivity check (docs/network.md)");
  if (net_.omega > 0)
    net_.notes.push_back("rotation: forced vortex per segment (pressure rise exact for isentropic rotation); node "
                         "temperatures stay at the supply's (the relative-frame rise is not carried)");
  return std::move(net_);
}

// A closed end beyond a passage's last exit carries no flow and is pruned from the network; where fewer
// than kMinSegments segments remain, the longest remaining ones (inner ones first: splitting the last one
// can move its end exit's station and prune it) get a station at their middle. Returns the new spans per
// passage (empty: every passage has enough).
std::map<std::string, std::vector<double>> stations_to_add(const Network& net) {
  std::map<std::string, std::vector<std::pair<double, double>>> live;
  for (const Element& e : net.elements)
    if (e.kind == ElementKind::Segment) live[e.chamber].emplace_back(std::min(e.span_in, e.span_out), std::max(e.span_in, e.span_out));
  std::map<std::string, std::vector<double>> add;
  for (auto& [name, segs] : live) {
    if (static_cast<int>(segs.size()) >= kMinSegments) continue;
    std::sort(segs.begin(), segs.end());
    std::vector<std::pair<double, double>> inner(segs.begin() + (segs.size() > 2 ? 1 : 0), segs.end() - (segs.size() > 2 ? 1 : 0));
    for (int k = static_cast<int>(segs.size()); k < kMinSegments; ++k) {
      auto longest = std::max_element(inner.begin(), inner.end(),
                                      [](const auto& x, const auto& y) { return x.second - x.first < y.second - y.first; });
      const double mid = 0.5 * (longest->first + longest->second), hi = longest->second;
      longest->second = mid;
      inner.emplace_back(mid, hi);
      add[name].push_back(mid);
    }
  }
  return add;
}

}  // namespace

Network build_network(const NetworkInput& in) {
  if (!in.config || !in.config->coolant || !in.model || !in.part || !in.passages)
    throw NetworkError("network: the build has no coolant section or no measured passages");
  // The end stations are cut on the built part; the report's sections too when an insert sits in a
  // chamber (the report cuts the blade alone: the insert's metal is not excluded there). Elsewhere the
  // report's sections are the built part's (walls closed over the holes), without cutting again.
  const auto [hub, tip] = end_station_spans(in);
  std::vector<double> spans{hub, tip};
  if (in.part->size() > 1)
    for (const features::PassageMeasure& m : in.passages->passages)
      for (const auto& s : m.sections) spans.push_back(s.span);
  Sections cuts = measure_stations(*in.model, *in.part, spans);
  std::map<std::string, std::vector<double>> extra;
  Network net = Builder(in, cuts, extra).run();
  for (int pass = 0; pass < 3; ++pass) {
    const std::map<std::string, std::vector<double>> add = stations_to_add(net);
    if (add.empty()) break;
    std::vector<double> more;
    for (const auto& [name, s] : add) {
      more.insert(more.end(), s.begin(), s.end());
      extra[name].insert(extra[name].end(), s.begin(), s.end());
    }
    for (auto& [name, secs] : measure_stations(*in.model, *in.part, more)) {
      auto& all = cuts[name];
      all.insert(all.end(), secs.begin(), secs.end());
    }
    net = Builder(in, cuts, extra).run();
  }
  return net;
}

}  // namespace cg::network
