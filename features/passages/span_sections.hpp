#pragma once
// Span sections of a (cooled) blade: the one section routine behind the design checks' passage
// cross-sections (passage_checks.hpp), sections.svg, report.md and report.json "sections".
//
// Each body of the part is cut by the span surface (section_surface.hpp: a plane on a straight vane,
// the streamline's surface of revolution on a rotor); the curves are traced on the exact faces and
// chained into closed loops through the edge crossings they end at (section_trace.hpp). Then:
//  - openings: a film or showerhead hole or a trailing-edge slot crossing the cut joins the cavity it
//    feeds to the outside (or notches a wall). Each run of a loop along an opening's faces ends on a
//    wall at both ends; the ends on one wall surface are joined by the curve of that surface across the
//    opening (trace_bridge), which closes the wall as designed. The walls' loops so closed are the
//    sealed loops (outer profile, cavities, islands); the opening's pieces with the same closing curves
//    bound the hole's section, listed as a hole, never as a passage;
//  - nesting of the sealed loops within a body (point in polygon): depth 0 outer profile, odd depth a
//    cavity, even depth > 0 a metal island (a pin fin cut across);
//  - passages: the cavities of body 0, each named by the passage its walls belong to (chamber_<k>_wall
//    -> chamber_<k>, radial_passage_<k>), loops of one passage summed (a pin fin cut along its axis
//    splits a chamber in two); area minus the islands and the metal of other bodies (inserts) inside,
//    wetted perimeter including them, D_h = 4 A / P. Over an opening the wall counts as closed (the
//    passage as designed), so the passages' areas equal those of the blade before its holes;
//  - areas: exact integrals along the traced curves in the surface's area coordinates (the true area on
//    a surface of revolution); lengths in 3D.
#include <Eigen/Core>
#include <string>
#include <vector>

#include "features/passages/section_surface.hpp"
#include "src/brep/named_shape.hpp"

namespace cg::features {

/// Faces of an opening in the wall (a hole's or slot's faces): film_row_*, showerhead_*, te_slot_*.
bool is_opening_face(const std::string& face_name);
/// The passage a face bounds: "chamber_<k>_wall" -> "chamber_<k>", "radial_passage_<k>" and "inlet_<k>"
/// (through the hub floor) -> themselves;
/// "" for any other face.
std::string passage_of_face(const std::string& face_name);

/// One traced curve as drawn (drawing coordinates of its surface).
struct SectionCurve {
  int body = 0;
  std::string name;  ///< the face it lies on
  std::vector<Eigen::Vector2d> points;
};

enum class SectionLoopKind { Outer, Cavity, Island, Hole };

struct SectionLoop {
  int body = 0;
  SectionLoopKind kind = SectionLoopKind::Outer;
  std::vector<Eigen::Vector2d> points;  ///< closed polygon (last point != first), drawing coordinates
  double area = 0;                      ///< mm^2, on the surface
  double perimeter = 0;                 ///< mm
  int depth = 0;                        ///< sealed loops of the same body around it
  std::string name;                     ///< passage (cavities), hole, or "" (outer, island)
};

struct SectionPassage {
  std::string name;                 ///< "chamber_2"; a cavity of several passages (a turnaround) "chamber_2 + chamber_3"
  double area = 0;                  ///< mm^2, coolant area
  double wetted_perimeter = 0;      ///< mm
  double hydraulic_diameter = 0;    ///< mm, 4 A / P
  int loops = 0;                    ///< cavity loops it has in this section
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero();  ///< of its largest loop, drawing coordinates
};

struct SectionHole {
  std::string name;  ///< the hole's (or slot's) face name, "film_row_1_hole_012"
  double area = 0;   ///< mm^2 of the hole's section in the metal
  Eigen::Vector2d centroid = Eigen::Vector2d::Zero();
};

struct SpanSection {
  double span = 0;
  std::vector<SectionCurve> curves;      ///< every body, as cut
  std::vector<SectionLoop> loops;        ///< sealed loops of every body and the holes' loops
  double metal_area = 0;                 ///< mm^2, all bodies, holes excluded
  double chord = 0;                      ///< mm, largest extent of the blade's outer loop (drawing coordinates)
  Eigen::Vector2d chord_a = Eigen::Vector2d::Zero(), chord_b = Eigen::Vector2d::Zero();
  std::vector<SectionPassage> passages;  ///< cavities of body 0, by name
  std::vector<SectionHole> holes;        ///< openings crossing the cut, by name
  int unclosed_openings = 0;             ///< openings whose walls could not be closed (their cavity stays joined)
};

/// The sections of every body of `part` by each surface (sections run side by side). Throws
/// FeatureFailure when a section curve cannot be followed or a loop does not close.
std::vector<SpanSection> span_sections(const brep::Part& part, const std::vector<SpanSurface>& surfaces);

}  // namespace cg::features
