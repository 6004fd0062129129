#pragma once
// The options of an import (plain data) and the counts they imply, known before any geometry is
// built (the config reader checks grid section indices against the number of cuts).
#include <algorithm>
#include <cstddef>

#include "src/blade/camber_edges.hpp"

namespace cg::blade_import {

struct ImportOptions {
  double tolerance = 0.01;    // mm: fidelity limit (fidelity.hpp) and LE/TE gap of the input sides
  int spans = 0;              // cuts from hub to casing; 0 = one per input section, in [11, 21]
  int samples_per_side = 0;   // chordwise samples per side; 0 = twice the most points on a side, in [96, 300]
  /// Where the LE and TE of an outline without sides (section tables, STEP / IGES cuts) are taken.
  blade::EdgeRule edges = blade::EdgeRule::CentreLine;
};

/// Stream-surface cuts the blade model is built from, for `input_sections` input sections (0: not
/// known before the geometry is read, e.g. a STEP file: 15).
inline int cut_count(const ImportOptions& o, std::size_t input_sections) {
  if (o.spans > 0) return o.spans;
  return input_sections == 0 ? 15 : std::clamp(static_cast<int>(input_sections), 11, 21);
}

}  // namespace cg::blade_import
