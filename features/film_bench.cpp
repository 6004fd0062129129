#include "features/film_bench.hpp"

#include <algorithm>
#include <cmath>

#include "features/film_rows.hpp"
#include "src/blade/blade_coordinates.hpp"

namespace cg::features {

FilmHoleTools film_bench_holes(const HoleTarget& target, int count, const FilmBenchOptions& o) {
  require(count >= 1, "film_bench_holes: count must be >= 1");
  const blade::BladeCoordinates coords(*target.model);
  RowPositioner positioner(coords);
  const double D = o.diameter;
  FilmLimits limits;
  HoleAnalyser analyser(target, limits);
  // Candidate rows every 5 D of arc length (at mid-span) across the band on each side.
  const auto [suction, pressure] = positioner.side_lengths(0.5);
  std::vector<FilmRowDefinition> rows;
  for (int side = 0; side < 2; ++side) {
    const double len = side == 0 ? suction : pressure, sign = side == 0 ? 1 : -1;
    for (double arc = o.chord_min * len; arc <= o.chord_max * len; arc += 5 * D) {
      FilmRowDefinition r;
      r.shape.diameter = D;
      r.position = {RowPosition::Kind::Chord, sign * arc / len};
      r.span_start = o.span_start;
      r.span_end = o.span_end;
      r.count = 3;
      r.inclination_deg = o.inclination_deg;
      try {
        // Probe: unstaggered (the hub end) and staggered by half a pitch (the last hole at span_end).
        for (double stagger : {0.0, 0.5}) {
          r.stagger = stagger;
          for (const HoleSpec& h : place_row(coords, positioner, r, 1, "probe")) analyser.analyse(h);
        }
      } catch (const FilmInputError&) {
        continue;  // over a rib, beyond an end wall or outside the core
      }
      rows.push_back(r);
    }
  }
  require(!rows.empty(), "film_bench_holes: no row of " + std::to_string(D) + " mm holes fits the blade");
  // Spread the holes over the rows; the pitch must stay >= pitch_d D.
  const int n_rows = static_cast<int>(rows.size());
  FilmCoolingDefinition def;
  for (int k = 0; k < n_rows; ++k) {
    FilmRowDefinition r = rows[k];
    r.count = count / n_rows + (k < count % n_rows ? 1 : 0);
    if (r.count == 0) continue;
    r.stagger = (k % 2) ? 0.5 : 0;
    def.rows.push_back(r);
  }
  std::vector<HoleSpec> holes;
  for (std::size_t k = 0; k < def.rows.size(); ++k) {
    const std::vector<HoleSpec> rh = place_row(coords, positioner, def.rows[k], static_cast<int>(k) + 1,
                                               "film_rows[" + std::to_string(k) + "]");
    if (!rh.empty() && rh.front().pitch < o.pitch_d * D)
      throw FilmInputError("film_rows[" + std::to_string(k) + "].count",
                           std::to_string(count) + " holes of " + std::to_string(D) + " mm need a pitch below " +
                               std::to_string(o.pitch_d) + " D on the " + std::to_string(n_rows) + " rows that fit");
    holes.insert(holes.end(), rh.begin(), rh.end());
  }
  return make_film_hole_tools(target, holes, limits);
}

}  // namespace cg::features
