#pragma once
// Hollow blades with one chamber to drill film holes into, for tests and benches (the configured
// cooling core of the passage features supplies the real chambers, ribs and end walls):
//  - make_film_hollow_blade: the blade minus the core bounded by the inner wall (the true 3D offset of the
//    wall by `wall` mm, src/blade/inner_wall.hpp) between a hub floor and a tip cap (the flow-path end
//    surfaces moved into the flow path by `end_wall` mm; radially for a meridional blade, as in
//    boolean_sample_part.hpp). One chamber, "chamber_1", whose wall faces are named chamber_1_wall.
//  - sample_hole_target: the HoleTarget of the boolean path's sample part (boolean_sample_part.hpp).
#include "tests/support/boolean_sample_part.hpp"
#include "features/film/hole_target.hpp"
#include "features/film/insert.hpp"
#include "src/blade/inner_wall.hpp"
#include "src/brep/named_shape.hpp"

namespace cg::features {

struct FilmHollowBlade {
  brep::NamedShape part;  ///< faces: blade_wall, hub, casing, chamber_1_wall, hub_floor, tip_cap
  blade::InnerWall inner;
  brep::EndTrim hub_floor, tip_cap;  ///< the end walls of the core
  double volume = 0;                 ///< mm^3 of the part
  double wall = 0, end_wall = 0;     ///< as built, mm
};

/// Throws InnerWallError when the wall is too thick for the blade, AlgorithmFailure when a boolean fails.
/// build_solid = false: only the inner wall and the end walls (enough for a HoleTarget), part left empty.
FilmHollowBlade make_film_hollow_blade(const blade::BladeModel& model, double wall, double end_wall, bool build_solid = true);

/// Moves an end trim by `shift` mm into the flow path (plane along its normal, meridional curve in r).
brep::EndTrim shifted_end_trim(const blade::BladeModel& model, bool hub, double shift);

/// The target of a hollow blade: its core surface, one chamber over the whole chord, the end walls as
/// obstacles (hole fields ".span_start" / ".span_end"). `model` and `hollow` must outlive it.
HoleTarget film_hollow_target(const blade::BladeModel& model, const FilmHollowBlade& hollow);
/// The insert chamber of a hollow blade: its whole core (chamber_1), end walls closed.
InsertChamber film_hollow_insert_chamber(const blade::BladeModel& model, const FilmHollowBlade& hollow);
HoleTarget sample_hole_target(const blade::BladeModel& model, const HollowBlade& part, const HollowBladeOptions& options);

}  // namespace cg::features
