#pragma once
// preview.png: a rendered 3D view of a brep::Part with the cooling visible. The outer metal faces
// (blade_wall, hub, casing, tip faces) are drawn semi-transparent, every other feature opaque in its
// kind's colour, so chambers, ribs and holes show through the wall; a legend names the kinds present.
// Rendered off screen with VTK (depth peeling for correct transparency) on an X display from
// ensure_x_display(); when none can be had the picture is skipped with a message, never an error.
#include <filesystem>
#include <string>

#include "export/triangulation.hpp"

namespace cg::io {

struct PreviewOptions {
  int width = 1280, height = 960;  ///< pixels
  double wall_opacity = 0.22;      ///< opacity of the outer metal faces, (0, 1]
  std::string title;               ///< drawn top left (e.g. the product name)
  /// Direction drawn upwards (hub -> casing); zero: the longest principal axis of the part.
  Eigen::Vector3d up = Eigen::Vector3d::Zero();
};

struct PreviewResult {
  bool written = false;
  std::string message;  ///< why it was skipped, or the display used
};

/// Renders the triangulated part to `file` (PNG, atomically). Skips (written = false) when no X display
/// is available; throws ExportError only when the file cannot be written.
PreviewResult write_preview(const std::filesystem::path& file, const PartTriangles& triangles,
                            const PreviewOptions& options = {});

/// Opacity a kind is drawn with: outer metal (blade_wall, hub, casing, tip_cap, hub_floor) at
/// `wall_opacity`, the walls of large cavities (chamber, turnaround) half transparent so inserts and
/// pin fins inside them show, every other feature opaque.
double kind_opacity(const std::string& kind, double wall_opacity);

}  // namespace cg::io
