#include "features/wall/cutback_wall.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "features/wall/trailing_edge.hpp"
#include "src/blade/inner_wall.hpp"
#include "src/core/format.hpp"
#include "src/core/newton.hpp"

namespace cg::features {
namespace {

constexpr double kLandGap = 0.25;   // mm, see the header comment
constexpr double kRamp = 0.06;      // chordwise coordinate: from the given wall to T_i
constexpr double kFootMargin = 0.005;  // chordwise coordinate: T_i this far upstream of the crease's feet
constexpr double kMaxFactor = 2.0;  // T_i at most twice the given wall
constexpr int kNodes = 20;          // span intervals

struct Node {
  double span = 0, thickness = 0;
};

// The nodes between the end walls with the wall each needs, and the most upstream crease feet of those
// needing more than the given wall (chordwise coordinates, kFootMargin upstream of them).
struct Nodes {
  std::vector<Node> nodes;
  double suction_from = 1, pressure_from = -1;
};

// How far the crease of a constant wall `thickness` at span s lies upstream of the lip less kLandGap
// (>= 0: far enough). Throws where the crease is lost (the section too thin for the wall).
double lip_excess(const blade::BladeCoordinates& coords, const CoreDefinition& def, double s, double thickness) {
  CoreDefinition d = def;
  d.wall_thickness = blade::ThicknessField::constant(thickness);
  return te_region_length(coords, d, s) - def.trailing_edge->cutback_length - kLandGap;
}

// The constant wall whose crease lies kLandGap upstream of the lip at span s, given the given wall t's
// excess f_t < 0; none when no wall up to kMaxFactor t does or the crease is lost on the way.
std::optional<double> needed_thickness(const blade::BladeCoordinates& coords, const CoreDefinition& def, double s, double f_t) {
  const double t = def.wall_thickness.min_value();
  auto excess = [&](double thickness) { return lip_excess(coords, def, s, thickness); };
  try {
    double lo = t, f_lo = f_t;
    for (double hi = 1.25 * t; hi <= kMaxFactor * t + 1e-12; hi += 0.25 * t) {
      const double f_hi = excess(hi);
      if (f_hi >= 0) return newton::solve_bracketed_secant(excess, lo, hi, f_lo, f_hi, 1e-4);
      lo = hi;
      f_lo = f_hi;
    }
  } catch (const std::exception&) {  // the crease lost: the section too thin for the wall
  }
  return std::nullopt;
}

// The ramp [from, to] (chordwise coordinate, one side) stays clear of the last rib's foot on that side
// and its fillet (+0.2 mm) at every node.
bool clear_of_last_rib(const blade::BladeCoordinates& coords, const CoreDefinition& def, const std::vector<Node>& nodes,
                       double from, bool suction) {
  if (def.ribs.empty()) return true;
  const RibDefinition& r = def.ribs.back();
  const double foot = suction ? r.suction_chord : r.pressure_chord;
  if (suction ? from <= foot : from >= foot) return false;
  for (const Node& n : nodes)
    if ((coords.frame(n.span, from).point - coords.frame(n.span, foot).point).norm() < 0.5 * r.thickness + r.fillet_radius + 0.2)
      return false;
  return true;
}

// The nodes over the slots' range, between the end walls (their thickness over the span's length at the
// LE; the table is constant beyond its first and last rows); those needing more than the given wall
// solved hardest first, so a design no wall can take is refused after one solve. None, with why_not,
// where a node finds no wall.
std::optional<Nodes> solve_nodes(const blade::BladeModel& model, const blade::BladeCoordinates& coords, const CoreDefinition& def,
                                 std::string& why_not) {
  const double t = def.wall_thickness.min_value(), len = model.span_length;
  const double s0 = def.hub_floor.open ? 0.0 : def.hub_floor.thickness / len;
  const double s1 = def.tip_cap.open ? 1.0 : 1.0 - def.tip_cap.thickness / len;
  Nodes out;
  std::vector<std::pair<double, std::size_t>> needing;  // (excess at t, node)
  for (int i = 0; i <= kNodes; ++i) {
    const double s = s0 + (s1 - s0) * i / kNodes;
    out.nodes.push_back({s, t});
    double f_t = 0;
    try {
      f_t = lip_excess(coords, def, s, t);
    } catch (const std::exception& e) {  // no crease at t at this span: nothing to move
      why_not = "the wall has no TE end to move at span " + format_number(s) + " (" + e.what() + ")";
      return std::nullopt;
    }
    if (f_t < 0) needing.emplace_back(f_t, out.nodes.size() - 1);
  }
  std::sort(needing.begin(), needing.end());
  for (const auto& [f_t, k] : needing) {
    Node& n = out.nodes[k];
    const std::optional<double> thickness = needed_thickness(coords, def, n.span, f_t);
    if (!thickness) {
      why_not = "no wall thickened toward the TE (to at most twice the given one, " + format_number(kMaxFactor * t) +
                " mm, and fitting the section) ends the chamber " + format_number(kLandGap) + " mm upstream of the lip at span " +
                format_number(n.span);
      return std::nullopt;
    }
    n.thickness = *thickness;
    const blade::InnerWallSection cr = blade::inner_wall_crease(coords, blade::ThicknessField::constant(n.thickness), n.span);
    out.suction_from = std::min(out.suction_from, cr.suction_chord - kFootMargin);
    out.pressure_from = std::max(out.pressure_from, cr.pressure_chord + kFootMargin);
  }
  return out;
}

}  // namespace

std::optional<CutbackWall> wall_for_cutback(const blade::BladeModel& model, const CoreDefinition& def, std::string& why_not) {
  why_not.clear();
  if (!def.trailing_edge || def.trailing_edge->type != TrailingEdgeType::PressureSideCutback) return std::nullopt;
  if (!def.wall_thickness.is_constant()) {
    why_not = "a tabulated wall_thickness is taken as given (thicken it toward the TE there)";
    return std::nullopt;
  }
  const blade::BladeCoordinates coords(model);
  const double t = def.wall_thickness.min_value();
  const std::optional<Nodes> solved = solve_nodes(model, coords, def, why_not);
  if (!solved) return std::nullopt;
  const std::vector<Node>& nodes = solved->nodes;
  const double suction_from = solved->suction_from, pressure_from = solved->pressure_from;
  const auto needing = [&](const Node& n) { return n.thickness > t; };
  const auto first = std::find_if(nodes.begin(), nodes.end(), needing);
  if (first == nodes.end()) return std::nullopt;
  const double suction_ramp = suction_from - kRamp, pressure_ramp = pressure_from + kRamp;
  const std::string ramp = " (from chord " + format_number(suction_ramp) + " on the suction side, " + format_number(pressure_ramp) +
                           " on the pressure side)";
  if (!(suction_from < 1 && pressure_from > -1 && pressure_ramp < 0 && suction_ramp > 0)) {
    why_not = "the wall thickened toward the TE to end the chamber there would reach the leading edge" + ramp;
    return std::nullopt;
  }
  if (!clear_of_last_rib(coords, def, nodes, suction_ramp, true) || !clear_of_last_rib(coords, def, nodes, pressure_ramp, false)) {
    why_not = "the wall thickened toward the TE to end the chamber there would reach rib " + std::to_string(def.ribs.size()) + ramp;
    return std::nullopt;
  }

  CutbackWall out;
  out.span_from = first->span;
  out.span_to = std::find_if(nodes.rbegin(), nodes.rend(), needing)->span;
  std::vector<double> spans;
  std::vector<std::vector<double>> values;
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    double T = nodes[i].thickness;
    if (i > 0) T = std::max(T, nodes[i - 1].thickness);
    if (i + 1 < nodes.size()) T = std::max(T, nodes[i + 1].thickness);
    out.max_thickness = std::max(out.max_thickness, T);
    spans.push_back(nodes[i].span);
    values.push_back({T, T, t, t, T, T});
  }
  out.wall_thickness = blade::ThicknessField::table(spans, {-1.0, pressure_from, pressure_ramp, suction_ramp, suction_from, 1.0},
                                                    values);
  out.note = "cooling.core.wall_thickness: the cutback's lip (cutback_length " + format_number(def.trailing_edge->cutback_length) +
             " mm) would lie over the last chamber of a " + format_number(t) + " mm wall: the wall is thickened toward the trailing edge, "
             "to at most " + format_number(out.max_thickness) + " mm from chord " + format_number(suction_from) + " (suction side) and " +
             format_number(pressure_from) + " (pressure side) on, from " + format_number(t) + " mm at " + format_number(suction_ramp) +
             " and " + format_number(pressure_ramp) + ", so the chamber ends " + format_number(kLandGap) + " mm upstream of the lip (spans " +
             format_number(out.span_from) + " to " + format_number(out.span_to) + " needed it)";
  return out;
}

}  // namespace cg::features
