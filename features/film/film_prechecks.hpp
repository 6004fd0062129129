#pragma once
// The film and insert checks that need only the blade model and the feature definitions: run by
// `coolinggen validate` and by a build before its first boolean (pipeline::plan_cooling), so a design
// the late checks would refuse after minutes of booleans is refused in milliseconds. Each is a necessary
// condition of what the hole analysis (hole_analysis.hpp) and the insert build check later on the built
// cavity, so it never refuses a design those accept:
//  - chamber references: film rows, the showerhead and inserts name a chamber that exists;
//  - the hole count stays below kMaxFilmHoles (a limit, not an attempt: thousands of tools would take
//    minutes to be refused by their ligaments);
//  - the ligament along a row: neighbours pitch P apart leave at most P - D of metal between their
//    metering bores (the bores' axes are at most P apart across them), so P - D < min_ligament fails;
//  - rows apart: two points on different holes' axes inside the wall at distance d leave at most d - D of
//    metal between the bores (the analysis bounds it from below), so d - D < min_ligament fails;
//  - the chamber a row feeds from: where each hole's axis has gone one wall thickness deep along the
//    wall normal (the cavity wall is the outer wall offset by that thickness) it is over chamber j; when
//    that point is clear of every rib by half its thickness + its fillet + the hole diameter, j is the
//    chamber the analysis will find, and a row that names another one is refused (near a rib it is left
//    to the analysis).
#include <vector>

#include "features/film/film_definition.hpp"
#include "features/film/hole_analysis.hpp"
#include "features/passages/passage_definition.hpp"
#include "src/blade/blade_surface.hpp"

namespace cg::features {

/// Film holes of one design above which it is refused (a limit, not an attempt).
constexpr std::size_t kMaxFilmHoles = 5000;

/// Throws FilmInputError naming the field below "cooling". `core` null: a blade without chambers.
/// `holes`: place_film_holes(model, def).
void check_film_definition(const blade::BladeModel& model, const CoreDefinition* core, const FilmCoolingDefinition& def,
                           const std::vector<HoleSpec>& holes);

}  // namespace cg::features
