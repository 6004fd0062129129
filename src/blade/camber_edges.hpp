#pragma once
// Leading and trailing edge of a closed section where its mean camber line ends (internal to the blade
// model; issue 31, for imported sections).
//
// The centre-line rule (leading_edge.hpp) puts the LE and TE where the line through both edge circles'
// centres leaves the profile: the cascade convention (C3X's published stagger is stated for it). Tools
// that build a profile from a camber line and a thickness (our parametric sections, T-Blade3, BladeGen)
// put them where the camber line ends. On a cambered blade with a round nose the two differ by the edge
// radius times the angle between the chord line and the camber line's end: 2 mm x 67 deg = 2.3 mm around
// the nose at the built-in rotor's hub, enough to move every feature placed by a chord fraction.
//
// Here the camber line near each edge is found in two stages. First estimate: the profile's medial axis,
// the centres of the circles inscribed in it touching each sample of the edge's neighbourhood (within 4
// edge radii of the edge circle's centre), fitted by a quadratic y(x) in the edge's frame (depth x from the
// edge circle's centre along the line through both centres, offset y across it). Then the midpoints of
// the profile's chords normal to that line (a profile built as camber +- thickness along the camber's
// normal has exactly these), 12 chords from R / 8 to 1.5 R deep, refitted six times in a frame turned to
// the line. The quadratic is continued outwards until it meets the profile: that point is the LE (TE).
// On the built-in rotor's three parametric sections (dense tables of them) the LE found lies within
// 0.036 mm and the TE within 0.0002 mm of the construction's (tests/blade/test_sections.cpp); the
// centre-line rule's are 1.4-2.5 mm and 0.28-0.46 mm away.
#include "src/blade/leading_edge.hpp"

namespace cg::blade {

/// Which point of each edge circle a detected section takes as its LE and TE.
enum class EdgeRule {
  CentreLine,  // where the line through both edge circles' centres leaves the profile (the default)
  CamberLine,  // where the profile's mean camber line, continued, meets the profile
};

/// LE and TE of the closed curve by the camber-line rule. `centre_line` is the detection by the
/// centre-line rule: its edge circles give each edge's centre, size and frame, its LE / TE where each
/// edge is. Throws InvalidGeometry when fewer than 6 inscribed circles or normal chords lie in an edge's
/// range or the continued camber line does not meet the profile within 4 edge radii.
LeadingTrailingEdge camber_edge_points(const BSplineCurve<2>& curve, const LeadingTrailingEdge& centre_line);

}  // namespace cg::blade
