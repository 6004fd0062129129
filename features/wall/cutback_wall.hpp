#pragma once
// A pressure-side cutback whose lip would lie over the last chamber: the wall thickened toward the
// trailing edge so that the chamber ends upstream of the lip and the slots run from it through metal
// (the TE land) to the lip, as a cast cutback does.
//
// The last chamber ends at the inner wall's crease, where the offsets of the two sides meet
// (src/blade/inner_wall.hpp); a thicker wall moves it upstream. At 21 span nodes between the end walls:
// the constant thickness T_i whose crease lies kLandGap upstream of the lip along the slot's frame
// (te_region_length = cutback_length + kLandGap: Illinois regula falsi on T, along which the crease
// moves monotonically upstream), or the given t where the crease already lies that far. Each T_i is
// then raised to its neighbours' largest: the table's interpolation along span stays between the
// nodes' values, so between two nodes it stays above what either node needs.
// The table (blade/thickness_field.hpp): T_i from the most upstream crease foot (over the nodes that
// need more than t, less 0.005) to the TE on both sides, the given t from kRamp (chordwise coordinate) further
// upstream on, monotone cubic between; the wall upstream of the ramp is the given one.
// kLandGap = 0.25 mm: the plan's check asks kLipClear (0.1 mm); the other 0.15 mm cover the slots'
// spans between the nodes.
#include <optional>
#include <string>

#include "features/passages/passage_definition.hpp"
#include "src/blade/blade_surface.hpp"
#include "src/blade/thickness_field.hpp"

namespace cg::features {

struct CutbackWall {
  blade::ThicknessField wall_thickness;  ///< the core's wall with the TE land
  double max_thickness = 0;              ///< mm, the largest T_i
  double span_from = 0, span_to = 0;     ///< the nodes that needed more than the given wall
  std::string note;                      ///< one line for the report and `coolinggen validate`
};

/// The wall of `def` (a pressure-side cutback, a constant wall) thickened toward the TE as above. None
/// when that cannot help, with `why_not` saying why for the refusal of cutback_length that then stands:
/// a tabulated wall (the user's own), a node needing more than twice t or losing its crease (the section
/// too thin for such a wall), the ramp reaching the last rib or its fillet (the ribs keep the given
/// wall); empty why_not: no cutback, or no node needing more than t.
std::optional<CutbackWall> wall_for_cutback(const blade::BladeModel& model, const CoreDefinition& def, std::string& why_not);

}  // namespace cg::features
