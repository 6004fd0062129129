#pragma once
// From 3D section tables (blade.import format "sections", section_table_reader.hpp) to an
// ImportedBlade: each table is one closed outline, checked first (one error each, naming the file, the
// section and a line: duplicated points, points out of order, an open outline, a crossing); its LE and
// TE are found as for planar point sections (blade::section_from_points' edge-circle detection, by the
// rule `edges`: camber_edges.hpp) on the
// outline unrolled onto its stream surface ((m, r theta) for annular rows, (x, y) for cascades), and
// the given points nearest to them split it into the suction side (the longer, as for turbine blades)
// and the pressure side, both LE -> TE. Hub and casing are the config's flow path.
#include <vector>

#include "src/blade/camber_edges.hpp"
#include "src/blade_import/imported_blade.hpp"
#include "src/blade_import/section_table_reader.hpp"

namespace cg::blade_import {

/// `hub`, `casing`: annular (x, r) contours; a cascade's are (x, 0) and (x, span). Throws
/// InvalidGeometry "<file>:<line>: section k: ...".
ImportedBlade blade_from_tables(const std::vector<SectionTable>& tables, RowKind kind, const std::vector<Eigen::Vector2d>& hub,
                                const std::vector<Eigen::Vector2d>& casing, blade::EdgeRule edges = blade::EdgeRule::CentreLine);

}  // namespace cg::blade_import
