#include "features/film/film_prechecks.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

#include "src/algo/segment_distance.hpp"
#include "src/blade/blade_coordinates.hpp"
#include "src/blade/inner_wall.hpp"
#include "src/core/format.hpp"

namespace cg::features {
namespace {

void check_chamber_reference(int chamber, int chambers, const std::string& field, const std::string& what) {
  if (chamber <= chambers) return;
  throw FilmInputError(field, what + ": there is no chamber_" + std::to_string(chamber) + " (" + std::to_string(chambers) +
                                  " chamber" + (chambers == 1 ? "" : "s") + "), must be in [1, " + std::to_string(chambers) + "]");
}

void check_references(const CoreDefinition* core, const FilmCoolingDefinition& def) {
  const int chambers = core ? static_cast<int>(core->ribs.size()) + 1 : 0;
  for (std::size_t i = 0; i < def.rows.size(); ++i)
    check_chamber_reference(def.rows[i].chamber, chambers, "film_rows[" + std::to_string(i) + "].chamber",
                            "film_row_" + std::to_string(i + 1));
  if (def.showerhead) check_chamber_reference(def.showerhead->chamber, chambers, "showerhead.chamber", "the showerhead");
  for (std::size_t i = 0; i < def.inserts.size(); ++i)
    check_chamber_reference(def.inserts[i].chamber, chambers, "inserts[" + std::to_string(i) + "].chamber",
                            "insert_" + std::to_string(i + 1));
}

void check_count_and_ligaments(const FilmCoolingDefinition& def, const std::vector<HoleSpec>& holes) {
  if (holes.size() > kMaxFilmHoles) {
    std::map<std::string, std::size_t> per_field;
    for (const HoleSpec& h : holes) ++per_field[h.field + h.spacing_field];
    const auto most = std::max_element(per_field.begin(), per_field.end(),
                                       [](const auto& a, const auto& b) { return a.second < b.second; });
    throw FilmInputError(most->first, std::to_string(holes.size()) + " film holes (" + std::to_string(most->second) +
                                          " from this row), more than the limit of " + std::to_string(kMaxFilmHoles) +
                                          ": widen the pitch or shorten the rows");
  }
  for (const HoleSpec& h : holes) {
    const double metal = h.pitch - h.shape.diameter;
    if (h.pitch > 0 && metal < def.limits.min_ligament) {
      const ValueLimitText t = format_value_limit(metal, def.limits.min_ligament, Allowed::above);
      throw FilmInputError(h.field + h.spacing_field,
                           h.row + ": holes of " + format_number(h.shape.diameter) + " mm at a pitch of " + format_number(h.pitch) +
                               (metal < 0 ? " mm overlap by " + format_number(-metal) + " mm"
                                          : " mm leave at most " + t.value + " mm of metal between neighbours") +
                               ", the ligament must be at least film_limits.min_ligament = " + t.limit + " mm");
    }
  }
}

// The chamber (1-based) the cavity wall's point at (span, chord) lies over, or 0 when it is closer to a
// rib than half its thickness + its fillet + `diameter` (left to the analysis).
int chamber_over(const blade::BladeCoordinates& coords, const CoreDefinition& core, double span, double chord, double diameter) {
  const Eigen::Vector3d p = blade::inner_wall_point(coords, core.wall_thickness, span, chord);
  int chamber = 1;
  for (const RibDefinition& r : core.ribs) {
    const double rib_chord = chord > 0 ? r.suction_chord : r.pressure_chord;
    const Eigen::Vector3d q = blade::inner_wall_point(coords, core.wall_thickness, span, rib_chord);
    if ((p - q).norm() < 0.5 * r.thickness + r.fillet_radius + diameter) return 0;
    if (std::abs(rib_chord) < std::abs(chord)) ++chamber;
  }
  return chamber;
}

// How far along its axis hole `h` stays in the wall (to one wall thickness deep along the exit's
// normal); 0 when the axis grazes the wall (the analysis decides).
double bore_depth(const blade::BladeCoordinates& coords, const CoreDefinition& core, const HoleSpec& h) {
  const blade::BladeFrame f = coords.frame(h.span, h.chord);
  const double sin_incl = -f.normal.dot(h.frame.axis);
  return sin_incl > 0.05 ? core.wall_thickness.at(h.span, h.chord) / sin_incl : 0.0;
}

// Holes of different rows: two points on the bores' axes at distance d put the bores' walls d - D
// apart along the line between them, so the least metal between the holes is at most d - D. The axes
// are taken from the exit to 0.9 of the bore depth (inside the wall). d - D below min_ligament fails
// the analysis' check (which bounds the metal from below) too: the later row is named, as there.
void check_rows_apart(const blade::BladeCoordinates& coords, const CoreDefinition& core, const FilmCoolingDefinition& def,
                      const std::vector<HoleSpec>& holes) {
  std::vector<double> depth(holes.size());
  for (std::size_t i = 0; i < holes.size(); ++i) depth[i] = 0.9 * bore_depth(coords, core, holes[i]);
  for (std::size_t i = 0; i < holes.size(); ++i)
    for (std::size_t j = i + 1; j < holes.size(); ++j) {
      const HoleSpec &a = holes[i], &b = holes[j];
      if (a.row == b.row || depth[i] <= 0 || depth[j] <= 0) continue;
      const double D = 0.5 * (a.shape.diameter + b.shape.diameter);
      if ((a.frame.exit - b.frame.exit).norm() > depth[i] + depth[j] + D + def.limits.min_ligament) continue;
      const double d = segment_distance(a.frame.exit, a.frame.exit + depth[i] * a.frame.axis, b.frame.exit,
                                        b.frame.exit + depth[j] * b.frame.axis);
      if (d - D < def.limits.min_ligament) {
        const ValueLimitText t = format_value_limit(d - D, def.limits.min_ligament, Allowed::above);
        throw FilmInputError(b.field + b.position_field,
                             "overlapping rows " + a.row + " and " + b.row + ": " + a.name + " and " + b.name +
                                 (d < D ? " overlap by " + format_number(D - d) + " mm" : " leave at most " + t.value + " mm of metal between them") +
                                 ", the ligament must be at least film_limits.min_ligament = " + t.limit + " mm");
      }
    }
}

void check_feeds(const blade::BladeCoordinates& coords, const CoreDefinition& core, const std::vector<HoleSpec>& holes) {
  for (const HoleSpec& h : holes) {
    if (h.required_chamber <= 0) continue;
    const double depth = bore_depth(coords, core, h);
    if (depth <= 0) continue;
    const blade::BladeLocateResult at = coords.locate(h.frame.exit + depth * h.frame.axis);
    if (!at.found || at.coordinate.chord * h.chord <= 0) continue;  // through the LE or TE: the analysis decides
    const int j = chamber_over(coords, core, at.coordinate.span, at.coordinate.chord, h.shape.diameter);
    if (j > 0 && j != h.required_chamber)
      throw FilmInputError(h.field + ".chamber",
                           h.name + " enters the cavity over chamber_" + std::to_string(j) + " (its axis is one wall thickness deep at "
                               "chord " + format_number(at.coordinate.chord) + ", span " + format_number(at.coordinate.span) +
                               "), not over chamber_" + std::to_string(h.required_chamber) + ": set chamber to " + std::to_string(j) +
                               " or move the row");
  }
}

}  // namespace

void check_film_definition(const blade::BladeModel& model, const CoreDefinition* core, const FilmCoolingDefinition& def,
                           const std::vector<HoleSpec>& holes) {
  check_references(core, def);
  check_count_and_ligaments(def, holes);
  if (!core) return;
  const blade::BladeCoordinates coords(model);
  check_feeds(coords, *core, holes);
  check_rows_apart(coords, *core, def, holes);
}

}  // namespace cg::features
