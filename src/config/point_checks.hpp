#pragma once
// Checks of a point section that the blade model makes too, made first here so that the message
// names the file lines (or the "values" entries) instead of point numbers counted from 0.
#include <string>

#include "src/blade/section.hpp"
#include "src/config/config.hpp"

namespace cg::config {

/// Refuses consecutive points that coincide and outlines that cross themselves (the tests and
/// tolerances of blade::section_from_points), naming "line 12" / "values[11]". Throws ConfigError.
void check_point_outline(const blade::PointSectionDefinition& def, const PointSource& source);

/// The advice for a failed LE/TE detection: give le_index and te_index, which count points from 0 in
/// the order given (with the file lines of the first and last point, so the user can count).
std::string le_te_index_hint(const blade::PointSectionDefinition& def, const PointSource& source);

}  // namespace cg::config
