#pragma once
// The curves in which a span surface (section_surface.hpp) cuts the faces of one body, traced on the
// exact surfaces. How:
//  1. every edge of the faces the surface can meet is cut once: g along its 3D curve, sampled (four per
//     continuity interval, at least 12; an interval without a sign change split until |g| at its ends
//     exceeds its length, as g is 1-Lipschitz), each sign change solved by bracketed secant. A crossing belongs to
//     the edge, so both faces at it end their curves at the same crossing: loops are chained by crossing,
//     never by a distance tolerance (edges of boolean results are up to 1e-3 mm and more off their faces);
//  2. on each face, from each of its crossings (in uv from the edge's curve on the face, heading inside:
//     left of the edge, which runs with the face on its left in uv), the zero set of f(u, v) = g(S(u, v))
//     is traced by predictor-corrector steps (tangent step, then Newton along grad f onto f = 0, to 1e-11
//     mm) of at most 1 mm and 0.1 rad of turning, and at most half the distance to the nearest other crossing
//     of the face, until it reaches one of them (ahead on the tangent): every curve piece ends exactly at
//     a crossing, however short (a piece cut off by a face corner) or long (the outer wall); the face's
//     classifier at every step catches a curve leaving the face where no crossing was found (an error);
//  3. curves that cross no edge (a loop inside one face) start from sign changes of f on a uv grid (two
//     nodes per knot interval or 12 per direction) that no traced piece passes through;
//  4. each step is integrated as the parabola through its ends and its midpoint (projected onto the curve):
//     twice the area (loop integral of a db - b da in the surface's area coordinates) and length.
// trace_bridge traces the same curve on a face's untrimmed surface between two crossings, to close
// the section over the opening a hole cuts into a wall (span_sections.hpp).
#include <BRepTopAdaptor_FClass2d.hxx>
#include <Bnd_Box.hxx>
#include <Geom_Surface.hxx>
#include <TopLoc_Location.hxx>
#include <TopTools_IndexedMapOfShape.hxx>
#include <gp_Pnt2d.hxx>

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "features/passages/section_surface.hpp"
#include "src/brep/named_shape.hpp"

namespace cg::features {

/// One body's faces and edges indexed for sections: boxes computed once, read by every section.
struct SectionBody {
  struct FaceEdge {
    int edge = 0;          ///< index into `edges` (1-based)
    bool reversed = false; ///< orientation in the FORWARD face
  };
  explicit SectionBody(const brep::NamedShape& body);

  const brep::NamedShape* shape = nullptr;
  std::vector<Bnd_Box> face_boxes;
  std::vector<std::vector<FaceEdge>> face_edges;
  TopTools_IndexedMapOfShape edges;
  std::vector<Bnd_Box> edge_boxes;  ///< [edge - 1]
  std::vector<Handle(Geom_Surface)> surfaces;  ///< per face
  std::vector<TopLoc_Location> locations;      ///< per face
  /// Faces a and b lie on one surface (one geometry, one location).
  bool same_surface(int a, int b) const;
};

/// Lazily built face classifiers of one body (one set per thread).
class FaceClassifiers {
 public:
  explicit FaceClassifiers(const SectionBody& body) : body_(&body), cls_(body.face_boxes.size()) {}
  BRepTopAdaptor_FClass2d& of(int face);

 private:
  const SectionBody* body_;
  std::vector<std::unique_ptr<BRepTopAdaptor_FClass2d>> cls_;
};

struct SectionCrossing {
  int edge = 0;  ///< 1-based index into SectionBody::edges
  double t = 0;  ///< edge curve parameter
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
};

/// Where a crossing lies on one of the faces at its edge.
struct SectionFaceVertex {
  int face = 0, crossing = 0;
  gp_Pnt2d uv;
  gp_Vec2d inward;  ///< normal of the face boundary in uv, into the face
};

struct SectionPiece {
  int face = -1;
  int first = -1, last = -1;          ///< crossings at its ends; both -1: a closed curve
  std::vector<Eigen::Vector3d> points;  ///< on the curve, first to last: step ends and midpoints alternately
  double green = 0;                   ///< integral of a db - b da along it (twice the signed area it adds)
  double length = 0;                  ///< mm
  bool bridge = false;                ///< traced by trace_bridge over an opening
};

struct SectionTrace {
  std::vector<SectionCrossing> crossings;
  std::vector<SectionFaceVertex> vertices;
  std::vector<SectionPiece> pieces;
};

/// Every curve of the section of `body` by the surface. Throws FeatureFailure when a curve cannot be
/// followed (it leaves a face away from every crossing, or does not reach one).
SectionTrace trace_section(const SectionBody& body, SpanSurfaceEvaluator& surface, FaceClassifiers& classifiers);

/// The curve from crossing vertex `a` to `b` on the untrimmed surface of face a.face (b on a face of the
/// same surface); none when it does not get there within a few times their distance.
std::optional<SectionPiece> trace_bridge(const SectionBody& body, const SectionFaceVertex& a, const SectionFaceVertex& b,
                                         const SectionTrace& trace, SpanSurfaceEvaluator& surface);

}  // namespace cg::features
