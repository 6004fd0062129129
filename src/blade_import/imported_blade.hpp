#pragma once
// An aerodynamic blade given by another tool, as read from its file (plain data, internal to the
// import): sections of points from hub to tip, each a suction and a pressure side running LE -> TE, and
// the channel (hub and casing contours). Everything is in CoolingGen's frame and millimetres: x is the
// engine axis, a point at radius r and angle theta is (x, r cos theta, r sin theta) (annular rows); a
// linear cascade is (x axial, y pitchwise, z spanwise) with the hub at z = 0.
#include <Eigen/Core>
#include <string>
#include <vector>

namespace cg::blade_import {

/// How the sections are laid out: an annular row (stream surfaces of revolution about x) or a linear
/// cascade (sections in planes z = const, hub and casing the planes z = 0 and z = span).
enum class RowKind { Annular, Cascade };

/// One input section: both sides LE -> TE (they share the LE and TE points) with the file line of every
/// point, so errors can name it.
struct ImportedSection {
  std::vector<Eigen::Vector3d> suction, pressure;  // mm, CoolingGen frame
  std::vector<int> suction_lines, pressure_lines;   // file line of each point
  int line = 0;                                     // file line where the section starts (suction side)
  std::string file;                                 // its own file (section tables); empty: the blade's
};

/// A point of the input's own surface (the faces of a STEP / IGES blade) inside the flow path, between
/// the input sections `section` and `section + 1`: the fidelity is measured there too, between the
/// sections the blade is rebuilt from.
struct SurfaceSample {
  Eigen::Vector3d point;  // mm, CoolingGen frame
  std::size_t section = 0;
  int face = 0;           // 1-based, in the file's order of faces
};

struct ImportedBlade {
  std::string file;     // as read (for messages)
  RowKind kind = RowKind::Annular;
  std::vector<ImportedSection> sections;  // hub -> tip
  /// Channel contours, upstream -> downstream: annular (x, r); cascade (x, z) with hub z = 0.
  std::vector<Eigen::Vector2d> hub, casing;
  int hub_line = 0, casing_line = 0;
  int number_of_blades = 0;                     // 0 = not given
  double tip_gap_le = 0, tip_gap_te = 0;        // mm, clearance between blade tip and casing
  std::vector<SurfaceSample> surface_samples;   // STEP / IGES: points on the input faces (else empty)

  /// The file section k came from (for messages).
  const std::string& file_of(std::size_t k) const {
    return k < sections.size() && !sections[k].file.empty() ? sections[k].file : file;
  }
};

}  // namespace cg::blade_import
