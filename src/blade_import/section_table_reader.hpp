#pragma once
// Reading 3D section point tables (blade.import format "sections"): one file per section, one point
// per line around the whole outline once (any start, either direction; a last point repeating the
// first is dropped). Columns, separated by whitespace, commas or semicolons: "x y z" (frame Xyz, the
// engine frame: x the axis; a straight flow path's x axial, y pitchwise, z spanwise) or "x r theta"
// (frame XRTheta: theta in degrees about the x axis, a point is (x, r cos theta, r sin theta)). Lengths
// in the given unit; '#' starts a comment line; blank lines are skipped; a first line that is not three
// numbers is a header and skipped. Syntax only: the outline's geometry is checked by table_blade.hpp.
#include <Eigen/Core>
#include <iosfwd>
#include <string>
#include <vector>

namespace cg::blade_import {

enum class TableFrame { Xyz, XRTheta };

/// One section's points in mm, CoolingGen frame (x, y, z), with the file line of each.
struct SectionTable {
  std::string file;
  std::vector<Eigen::Vector3d> points;
  std::vector<int> lines;
};

/// Throws InvalidGeometry "<file>:<line>: <what>" for a line that is not three finite numbers, a
/// radius <= 0, fewer than 8 points, or a file that cannot be read.
SectionTable read_section_table(const std::string& path, TableFrame frame, double mm_per_unit);
SectionTable parse_section_table(std::istream& in, const std::string& name, TableFrame frame, double mm_per_unit);

}  // namespace cg::blade_import
