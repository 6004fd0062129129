#include "tests/support/drill_sample_holes.hpp"

#include <BRepTopAdaptor_FClass2d.hxx>
#include <BRep_Tool.hxx>
#include <Geom_BSplineSurface.hxx>
#include <Geom_CylindricalSurface.hxx>
#include <Geom_Plane.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include "adaptors/occt_convert.hpp"
#include "features/drilling/drill_hole_geometry.hpp"
#include "src/blade/blade_coordinates.hpp"
#include "src/core/constants.hpp"
#include "src/core/error.hpp"

namespace cg::features {
namespace {

using cg::kPi;

// The chamber walls of the part: their common surface and a classifier per face.
struct ChamberWalls {
  std::unique_ptr<WallSurface> surface;
  std::vector<std::unique_ptr<BRepTopAdaptor_FClass2d>> faces;
  // Index of the chamber wall face holding (u, v) strictly inside, -1: none.
  int face_at(double u, double v) const {
    for (std::size_t k = 0; k < faces.size(); ++k)
      if (faces[k]->Perform(gp_Pnt2d(u, v)) == TopAbs_IN) return static_cast<int>(k);
    return -1;
  }
};

ChamberWalls chamber_walls(const brep::NamedShape& part) {
  ChamberWalls w;
  const Geom_Surface* common = nullptr;
  for (const brep::NamedFace& f : part.faces) {
    if (f.name.rfind("chamber_", 0) != 0 || f.name.size() < 5 || f.name.compare(f.name.size() - 5, 5, "_wall") != 0)
      continue;
    TopLoc_Location loc;
    const Handle(Geom_Surface) s = BRep_Tool::Surface(f.face, loc);
    const auto bs = Handle(Geom_BSplineSurface)::DownCast(s);
    require(bs && loc.IsIdentity() && (!common || common == s.get()),
            "film_hole_field: the chamber walls must lie on one B-spline surface");
    if (!common) w.surface = std::make_unique<WallSurface>(std::make_shared<const BSplineSurface<3>>(occt::from_occt(*bs)));
    common = s.get();
    w.faces.push_back(std::make_unique<BRepTopAdaptor_FClass2d>(TopoDS::Face(f.face.Oriented(TopAbs_FORWARD)), 1e-9));
  }
  require(common != nullptr, "film_hole_field: the part has no chamber_<k>_wall faces");
  return w;
}

// A hole at (span, x) on one side (x > 0 suction, < 0 pressure), or none when its exit ring does not
// lie on one chamber wall face or the cavity behind it is too thin.
bool place_hole(const blade::BladeCoordinates& bc, ChamberWalls& walls, WallSurface& outer, double span, double x,
                const FilmFieldOptions& o, CylindricalHole& hole) {
  const double r = 0.5 * o.diameter, a = o.inclination_deg * kPi / 180;
  const blade::BladeFrame f = bc.frame(span, x);
  const Eigen::Vector3d down = x > 0 ? f.chord_tangent : Eigen::Vector3d(-f.chord_tangent);
  const Eigen::Vector3d d = (-std::sin(a) * f.normal - std::cos(a) * down).normalized();
  const double s_out = (o.clearance + r * std::cos(a)) / std::sin(a) + 0.1;
  const Eigen::Vector3d start = f.point - s_out * d;
  const HoleCylinder c = HoleCylinder::from_axis(start, d, r, 1);
  double t_exit = 0;
  int face = -2;
  for (int k = 0; k <= 16; ++k) {
    // k < 16: the ring r + margin; k = 16: the axis.
    const Eigen::Vector3d p = k < 16 ? c.ruling(2 * kPi * k / 16, r + o.ring_margin) : start;
    const RaySurfaceHit ho = outer.first_hit(p, d, 30), hi = walls.surface->first_hit(p, d, 30);
    if (!ho.found || !hi.found || hi.ray_param <= ho.ray_param) return false;
    const int fk = walls.face_at(hi.u, hi.v);
    if (fk < 0 || (face != -2 && fk != face)) return false;
    face = fk;
    t_exit = std::max(t_exit, hi.ray_param);
    // The cavity behind the exit must hold the tool's end.
    const RaySurfaceHit far = walls.surface->first_hit(p + (hi.ray_param + 1e-6) * d, d, 30);
    if (far.found && far.ray_param < (o.clearance + r * std::cos(a)) / std::sin(a) + 0.2) return false;
  }
  hole.origin = start;
  hole.axis = d;
  hole.diameter = o.diameter;
  hole.length = t_exit + o.clearance / std::sin(a) + r * std::cos(a) / std::sin(a);
  return true;
}

}  // namespace

std::vector<CylindricalHole> film_hole_field(const blade::BladeModel& model, const brep::NamedShape& part,
                                             const FilmFieldOptions& o) {
  require(o.count >= 1 && o.diameter > 0 && o.inclination_deg >= 10 && o.inclination_deg <= 90,
          "film_hole_field: count >= 1, diameter > 0 and inclination in [10, 90] degrees required");
  const blade::BladeCoordinates bc(model);
  ChamberWalls walls = chamber_walls(part);
  WallSurface outer(std::make_shared<const BSplineSurface<3>>(model.surface));
  const double a = o.inclination_deg * kPi / 180;

  // Candidate rows: chord positions on each side whose holes exit onto a chamber wall at five spans.
  struct Row {
    double x, s;  // signed chord coordinate, arc length along the side at mid-span (mm)
  };
  std::vector<Row> rows;
  constexpr int kCandidates = 120;
  for (const int side : {1, -1}) {
    double s = 0;
    Eigen::Vector3d prev = bc.frame(0.5, side * o.chord_min).point;
    for (int k = 0; k <= kCandidates; ++k) {
      const double x = o.chord_min + (o.chord_max - o.chord_min) * k / kCandidates;
      const Eigen::Vector3d p = bc.frame(0.5, side * x).point;
      s += (p - prev).norm();
      prev = p;
      bool ok = true;
      CylindricalHole h;
      for (int j = 0; j < 5 && ok; ++j)
        ok = place_hole(bc, walls, outer, o.span_min + (o.span_max - o.span_min) * j / 4, side * x, o, h);
      if (ok) rows.push_back({side * x, side * s});
    }
  }
  // Rows at least one footprint (D / sin a) plus the gap apart along the surface, greedily.
  const double row_pitch = o.diameter / std::sin(a) + o.min_row_gap;
  std::vector<Row> kept;
  for (const Row& r : rows)
    if (kept.empty() || (kept.back().x > 0) != (r.x > 0) || std::abs(r.s - kept.back().s) >= row_pitch) kept.push_back(r);
  require(!kept.empty(), "film_hole_field: no chordwise position exits onto a chamber wall");
  const double span_len = (bc.frame(o.span_max, kept[0].x).point - bc.frame(o.span_min, kept[0].x).point).norm();
  const int per_row_max = std::max(1, static_cast<int>(span_len / o.min_pitch));
  // As few rows as the count needs, spread over the kept positions; holes the direct drilling would
  // not take (a rib or fillet within reach, too close to an edge of their faces) are dropped, and rows
  // are added until `count` remain.
  std::vector<CylindricalHole> holes;
  const int min_rows = (o.count + per_row_max - 1) / per_row_max;
  const int max_rows = static_cast<int>(kept.size());
  for (int n_rows = std::min(min_rows, max_rows), last = 0; !last && static_cast<int>(holes.size()) < o.count;
       n_rows = std::min(max_rows, n_rows + 1 + n_rows / 8)) {
    last = n_rows == max_rows;
    const int in_row = last ? per_row_max : std::min(per_row_max, (o.count + n_rows - 1) / n_rows + 1);
    std::vector<CylindricalHole> grid;
    for (int row = 0; row < n_rows; ++row) {
      const Row& at = kept[static_cast<std::size_t>(n_rows == 1 ? kept.size() / 2 : row * (kept.size() - 1) / (n_rows - 1))];
      const double stagger = (row % 2) * 0.5;
      for (int j = 0; j < in_row; ++j) {
        const double span = o.span_min + (o.span_max - o.span_min) * (j + 0.25 + stagger) / in_row;
        CylindricalHole h;
        if (!place_hole(bc, walls, outer, span, at.x, o, h)) continue;
        char name[64];
        std::snprintf(name, sizeof name, "%s%d_hole_%03d", o.name_prefix.c_str(), row + 1, j + 1);
        h.name = name;
        grid.push_back(h);
      }
    }
    const std::vector<std::string> reasons = drill_fallback_reasons(part, grid);
    holes.clear();
    for (std::size_t k = 0; k < grid.size(); ++k)
      if (reasons[k].empty()) holes.push_back(grid[k]);
  }
  require(static_cast<int>(holes.size()) >= o.count,
          "film_hole_field: only " + std::to_string(holes.size()) + " of " + std::to_string(o.count) +
              " holes fit onto the chamber walls (" + std::to_string(kept.size()) + " rows of at most " +
              std::to_string(per_row_max) + ")");
  // Every k-th hole, so the field stays spread over all rows.
  std::vector<CylindricalHole> out;
  for (int k = 0; k < o.count; ++k) out.push_back(holes[static_cast<std::size_t>(static_cast<long>(k) * static_cast<long>(holes.size()) / o.count)]);
  return out;
}

std::vector<CylindricalHole> holes_of_tools(const std::vector<FeatureTool>& tools) {
  std::vector<CylindricalHole> out;
  for (const FeatureTool& t : tools) {
    require(t.symmetry_axis.has_value(), "holes_of_tools: tool '" + t.feature + "' has no axis");
    const gp_Ax1& ax = *t.symmetry_axis;
    const gp_Vec d(ax.Direction());
    CylindricalHole h;
    h.name = t.feature;
    h.origin = Eigen::Vector3d(ax.Location().X(), ax.Location().Y(), ax.Location().Z());
    h.axis = Eigen::Vector3d(d.X(), d.Y(), d.Z());
    for (TopExp_Explorer e(t.shape.shape, TopAbs_FACE); e.More(); e.Next()) {
      const Handle(Geom_Surface) s = BRep_Tool::Surface(TopoDS::Face(e.Current()));
      if (const auto pl = Handle(Geom_Plane)::DownCast(s))
        h.length = std::max(h.length, gp_Vec(ax.Location(), pl->Location()).Dot(d));
      else if (const auto cy = Handle(Geom_CylindricalSurface)::DownCast(s))
        h.diameter = 2 * cy->Radius();
    }
    require(h.length > 0 && h.diameter > 0, "holes_of_tools: tool '" + t.feature + "' is not a cylinder");
    out.push_back(h);
  }
  return out;
}

}  // namespace cg::features
