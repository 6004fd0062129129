#pragma once
// sections.svg: the section cuts drawn side by side at one common scale: metal filled (blade grey,
// other bodies such as inserts green), every section edge stroked in the colour of its feature kind,
// the chord as a dimension line with its length, coolant passages numbered with their area and
// hydraulic diameter, the holes crossing the cut counted with their area (left unfilled in the metal),
// a 10 mm (or fitting) scale bar per panel and a legend of the kinds drawn.
#include <filesystem>
#include <string>
#include <vector>

#include "features/passages/span_sections.hpp"

namespace cg::io {

/// The SVG text (for tests and other writers).
std::string sections_svg(const std::vector<features::SpanSection>& cuts, const std::string& title);

/// Writes sections_svg(...) atomically. Throws ExportError.
void write_sections_svg(const std::filesystem::path& file, const std::vector<features::SpanSection>& cuts, const std::string& title);

}  // namespace cg::io
