#pragma once
// Blade-relative coordinates, so that cooling features move with the blade (issue 8, item 3):
//   span   = span fraction, the surface v: 0 on the hub streamline, 1 on the casing streamline, and the
//            section at span s lies on the stream surface at s (straight vane: the plane z = s * span),
//            within the model's surface_tolerance; the over-build extends it slightly beyond [0, 1];
//   chord  = chordwise coordinate in [-1, 1] on the section at that span (span_section.hpp): the
//            arc-length fraction of the side from the LE, (0, 1] over the suction side, [-1, 0) over the
//            pressure side; +1 and -1 are both exactly the TE;
//   depth  = distance into the wall along the inward normal, mm (0 on the surface, > 0 inside).
// point = S(u, v) - depth * n(u, v), n the outward unit normal, u = the section's u at that chord.
// The wall's periodic seam is the iso-line u = 0 (seam_u()), at chordwise coordinate seam_chordwise(span)
// (+1, the middle of the TE, by default).
#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>  // (kept for includers)
#include <vector>

#include "src/blade/blade_surface.hpp"
#include "src/blade/span_section.hpp"

namespace cg {
class SurfaceProjector;
}

namespace cg::blade {

struct BladeCoordinate {
  double span = 0;
  double chord = 0;
  double depth = 0;
};

/// Local frame at a surface point.
struct BladeFrame {
  Eigen::Vector3d point = Eigen::Vector3d::Zero();          // on the surface (depth 0)
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();         // outward unit normal
  Eigen::Vector3d span_tangent = Eigen::Vector3d::Zero();   // unit dS/dv (hub -> casing)
  Eigen::Vector3d chord_tangent = Eigen::Vector3d::Zero();  // unit dS/du (LE -> TE on the suction side,
                                                            // TE -> LE on the pressure side)
  double u = 0, v = 0;                                      // surface parameters
};

struct BladeLocateResult {
  bool found = false;
  BladeCoordinate coordinate;
  double u = 0, v = 0;  // surface parameters of the foot point
};

/// One per thread (it caches the sections of the spans used last and reuses the projector's work
/// buffers); the model must outlive it.
class BladeCoordinates {
 public:
  explicit BladeCoordinates(const BladeModel& model);
  ~BladeCoordinates();
  BladeCoordinates(const BladeCoordinates&) = delete;
  BladeCoordinates& operator=(const BladeCoordinates&) = delete;

  /// The frame at (span, chord); Near: the chord to within 1e-4 of the section's length, for scans
  /// (chordwise.hpp: the frame is exact at the surface point it lands on).
  BladeFrame frame(double span, double chord, ChordAccuracy accuracy = ChordAccuracy::Exact) const;
  /// The frame at surface parameters (u, v) (v: the span; u wrapped by its period).
  BladeFrame frame_at(double u, double v) const;
  Eigen::Vector3d point(const BladeCoordinate& c) const;
  /// Inverse by global orthogonal projection onto the surface (src/algo/project_point_surface), then the
  /// chordwise coordinate of the foot point on its span's section. found=false when the closest point
  /// lies on the over-build end (v at the domain boundary with the point beyond it). Exact inverse of
  /// point() while depth is below the local half-thickness and radius of curvature (the closest surface
  /// point is then the one the point was built from).
  BladeLocateResult locate(const Eigen::Vector3d& p) const;
  /// The section at a span (the one definition of chord and LE/TE, span_section.hpp). Sections are
  /// cached per span (exact match, the kSectionCacheSize spans used last): callers alternate between a
  /// few spans (a rib between its two walls, a difference quotient across the span), and every section
  /// costs an arc-length table. The reference stays valid until kSectionCacheSize other spans are used.
  const SpanSection& section(double span) const;
  static constexpr std::size_t kSectionCacheSize = 48;

  /// The seam: surface u = 0, at this chordwise coordinate on the given span.
  static constexpr double seam_u() { return 0.0; }
  double seam_chordwise(double span) const { return section(span).seam_chordwise(); }

  const BladeModel& model() const { return *model_; }

 private:
  const BladeModel* model_;
  double normal_sign_ = 1;  // +1 when S_u x S_v points outward
  std::unique_ptr<SurfaceProjector> projector_;
  std::shared_ptr<const IsoArcLengthNodes> iso_nodes_;  // Gauss nodes shared by every span's section
  struct CachedSection {
    double span = 0;
    std::uint64_t last_used = 0;  // cache clock at the last use (least recently used goes first)
    std::unique_ptr<const SpanSection> section;  // owned apart, so references survive other insertions
  };
  mutable std::vector<CachedSection> cache_;
  mutable std::size_t last_hit_ = 0;  // index of the entry used last (checked first)
  mutable std::uint64_t clock_ = 0;
};

}  // namespace cg::blade
