#pragma once
// Film-hole work loads for benches (bench/bench_holes.cpp measures the verified boolean path on them):
// `count` cylindrical holes in rows on a cooled blade, placed, analysed and checked like configured rows.
#include "features/film_holes.hpp"
#include "features/hole_target.hpp"

namespace cg::features {

struct FilmBenchOptions {
  double diameter = 0.3;         ///< mm
  double pitch_d = 3.5;          ///< least pitch along a row, in D
  double inclination_deg = 30;
  double span_start = 0.12, span_end = 0.88;
  /// Chordwise band searched for rows on each side (magnitudes; pressure side mirrored).
  double chord_min = 0.12, chord_max = 0.8;
};

/// `count` holes (film_row_<k>_hole_<nnn>) in rows over both sides of the target's blade: candidate rows
/// every 5 D of arc length across the band are kept where their holes enter a chamber clear of ribs and
/// end walls; the holes are spread over the kept rows (alternate rows staggered by half a pitch), the
/// pitch no less than pitch_d D. Each hole is analysed (expected volume by ray quadrature) and made into
/// a tool. Throws FilmInputError when the blade cannot take `count` holes at that pitch.
FilmHoleTools film_bench_holes(const HoleTarget& target, int count, const FilmBenchOptions& options = {});

}  // namespace cg::features
