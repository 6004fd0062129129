#pragma once
// The coolant circuit of a built blade as a flow network (docs/network.md): plain data, filled from the
// built part and its reports by build_network() (network_graph.hpp), written as network.json
// (network_json.hpp) and as a CalculiX deck (ccx_deck.hpp). Lengths mm, areas mm^2, angles degrees,
// pressures Pa, temperatures K.
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace cg::network {

inline constexpr double kUnset = std::numeric_limits<double>::quiet_NaN();

enum class NodeKind {
  Supply,    ///< a plenum at fixed total pressure and temperature (the coolant supply)
  Junction,  ///< a station in the circuit: chamber section, plenum inside an insert
  Sink,      ///< the outside at fixed static pressure (the hot gas at a kind of exit)
};

struct Node {
  int id = 0;           ///< 1-based
  std::string name;     ///< "supply", "chamber_2_s03", "sink_suction_side"
  NodeKind kind = NodeKind::Junction;
  std::string chamber;  ///< the chamber of a station ("" otherwise)
  double span = kUnset;    ///< span fraction of a station
  double radius = kUnset;  ///< mm from the rotation axis (x) of a station, rotors
  double pressure = kUnset;     ///< Pa: supply total pressure, sink static pressure
  double temperature = kUnset;  ///< K: supply total temperature
};

enum class ElementKind {
  Inlet,          ///< hole through an end wall from the supply into a chamber
  Segment,        ///< part of a chamber between two measured sections
  Bend,           ///< 180 deg turnaround between two chambers
  Rotation,       ///< centrifugal pumping of a segment of a rotor (forced vortex)
  Jets,           ///< impingement jet holes of an insert (one element, `count` holes)
  FilmHole,       ///< one film or showerhead hole
  Slot,           ///< one trailing-edge slot
  PinBank,        ///< a slot's share of the pin-fin bank in front of it (Metzger's loss, docs/network.md)
};

/// Rib turbulators along a segment.
struct Turbulation {
  double e_dh = 0, p_e = 0, angle_deg = 90;
  std::string walls;  ///< "both" | "suction" | "pressure"
  int count = 0;      ///< turbulator faces' numbers on the segment (built)
  double height = 0, pitch = 0;
  double friction_factor = 0;  ///< Fanning, fully rough, ribbed walls (docs/network.md)
  double ribbed_fraction = 0;  ///< of the wetted perimeter
};

/// Staggered pin-fin rows upstream of the slots (one slot's share of the bank).
struct PinBank {
  double diameter = 0, s_d = 0, x_d = 0;
  int rows = 0, pins = 0;
  double height = 0;        ///< mm, the pins' mean length across the chamber (their faces on the part)
  double gap_area = 0;      ///< mm^2, one slot's share of the minimum gap between the pins of a row
  double re_d = 1e4;        ///< Reynolds number (pin diameter, gap velocity) of the loss: the solved flow's once solved
  double loss_per_row = 0;  ///< velocity heads per row at the minimum gap at re_d (docs/network.md)
};

/// A film or showerhead hole, a slot, or an insert's jets.
struct Opening {
  std::string row;      ///< "film_row_2", "showerhead_1", "te_slots", "insert_1"
  std::string shape;    ///< "cylindrical", "fan_shaped", "slot"
  double diameter = 0;  ///< mm (slots: hydraulic diameter)
  double metering_length = 0, length_d = 0;
  double inclination_deg = kUnset, compound_deg = kUnset;
  double metering_area = 0, exit_area = 0, area_ratio = 1;
  int count = 1;                       ///< holes in the element (jets: all of the insert)
  double z_d = kUnset, x_d = kUnset, y_d = kUnset;  ///< jets
  std::string sink;                    ///< "suction_side", ...
  int hole_index = -1;                 ///< into FilmReport::holes
};

struct Element {
  int id = 0;  ///< 1-based
  std::string name;
  ElementKind kind = ElementKind::Segment;
  int upstream = 0, downstream = 0;  ///< node ids
  std::string chamber;               ///< the chamber it belongs to or leaves from
  std::string enters_from;           ///< openings: the segment their inlet lies on
  double length = 0;
  double area_in = 0, area_out = 0;             ///< flow area at both ends
  double perimeter_in = 0, perimeter_out = 0;   ///< wetted perimeter at both ends
  double hydraulic_diameter = 0;                ///< 4 A / P, mean of both ends
  double aspect_ratio = kUnset;                 ///< of the rectangle with the same A and P (>= 1)
  double roughness = 0;                         ///< equivalent sand roughness used in the deck
  double span_in = kUnset, span_out = kUnset;
  double radius_in = kUnset, radius_out = kUnset;  ///< mm from the rotation axis
  double bend_angle_deg = kUnset, bend_radius = kUnset;
  double bend_gap = kUnset, bend_depth = kUnset;  ///< turnaround: rib tip to end wall, cavity depth there (mm)
  std::optional<Turbulation> turbulators;
  std::optional<PinBank> pins;      ///< pin banks: the pins in front of a slot
  std::optional<Opening> opening;
  std::vector<std::string> faces;  ///< names of the faces it comes from
};

struct Gas {
  double gas_constant = 287.05;  ///< J/(kg K)
  double cp = 1005;              ///< J/(kg K)
  double viscosity = 1.8e-5;     ///< Pa s
};

struct Network {
  std::vector<Node> nodes;
  std::vector<Element> elements;
  Gas gas;
  double omega = 0;  ///< rad/s about the x axis
  std::vector<std::string> notes;  ///< what the network leaves out for this blade
  const Node& node(int id) const { return nodes.at(static_cast<std::size_t>(id - 1)); }
};

const char* name(NodeKind k);
const char* name(ElementKind k);

}  // namespace cg::network
