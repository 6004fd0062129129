#include "src/mesh/surface_mesh.hpp"

#include <BRepAdaptor_Surface.hxx>
#include <BRep_Tool.hxx>
#include <TopExp_Explorer.hxx>
#include <TopoDS.hxx>
#include <gmsh.h>

#include <Eigen/Geometry>

#include <set>
#include <unordered_map>

#include "src/mesh/coolant_domain.hpp"
#include "src/mesh/gmsh_session.hpp"

namespace cg::mesh {
namespace {

constexpr int kFrontalDelaunay = 6, kDelaunay = 5, kMeshAdapt = 1;

// gmsh meshes a face with its periodic mesher when the surface is periodic or the face has a seam edge
// (OCCFace::periodic, OCCEdge::isSeam: the same OCCT queries).
bool meshed_as_periodic(const TopoDS_Face& face) {
  const BRepAdaptor_Surface s(face, false);
  if (s.IsUPeriodic() || s.IsVPeriodic()) return true;
  for (TopExp_Explorer e(face, TopAbs_EDGE); e.More(); e.Next())
    if (BRep_Tool::IsClosed(TopoDS::Edge(e.Current()), face)) return true;
  return false;
}

int boundary_curves(int tag) {
  gmsh::vectorpair curves;
  gmsh::model::getBoundary({{2, tag}}, curves, false, false, false);
  std::set<int> unique;
  for (const auto& [dim, t] : curves) unique.insert(std::abs(t));
  return static_cast<int>(unique.size());
}

// Triangles of surface `tag` whose normal points against the surface normal (gmsh orients every
// surface mesh along the surface normal, so a valid mesh has none). The surface normal of a triangle
// is taken at one of its nodes inside the surface (gmsh keeps their (u, v)), else at the projection of
// its centroid.
std::size_t folded_triangles(int tag) {
  std::vector<std::size_t> elements, tri;
  gmsh::model::mesh::getElementsByType(2, elements, tri, tag);
  if (tri.empty()) return 0;
  std::vector<std::size_t> all, inner;
  std::vector<double> xyz, unused, inner_xyz, inner_uv;
  gmsh::model::mesh::getNodes(all, xyz, unused, 2, tag, true, false);
  gmsh::model::mesh::getNodes(inner, inner_xyz, inner_uv, 2, tag, false, true);
  std::unordered_map<std::size_t, std::size_t> at, inner_at;
  for (std::size_t i = 0; i < all.size(); ++i) at[all[i]] = i;
  for (std::size_t i = 0; i < inner.size(); ++i) inner_at[inner[i]] = i;

  const std::size_t n = tri.size() / 3;
  std::vector<double> uv(2 * n), normal_of(3 * n), centroids;
  std::vector<std::size_t> projected;  // triangles without an inner node
  for (std::size_t t = 0; t < n; ++t) {
    Eigen::Vector3d p[3];
    bool found = false;
    for (int k = 0; k < 3; ++k) {
      const std::size_t node = tri[3 * t + static_cast<std::size_t>(k)];
      const std::size_t i = at.at(node);
      p[k] = {xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]};
      const auto in = inner_at.find(node);
      if (!found && in != inner_at.end()) {
        uv[2 * t] = inner_uv[2 * in->second];
        uv[2 * t + 1] = inner_uv[2 * in->second + 1];
        found = true;
      }
    }
    const Eigen::Vector3d c = (p[1] - p[0]).cross(p[2] - p[0]);
    for (int j = 0; j < 3; ++j) normal_of[3 * t + static_cast<std::size_t>(j)] = c[j];
    if (!found) {
      const Eigen::Vector3d m = (p[0] + p[1] + p[2]) / 3;
      centroids.insert(centroids.end(), {m.x(), m.y(), m.z()});
      projected.push_back(t);
    }
  }
  if (!projected.empty()) {
    std::vector<double> puv;
    gmsh::model::getParametrization(2, tag, centroids, puv);
    for (std::size_t k = 0; k < projected.size(); ++k) {
      uv[2 * projected[k]] = puv[2 * k];
      uv[2 * projected[k] + 1] = puv[2 * k + 1];
    }
  }
  std::vector<double> normals;
  gmsh::model::getNormal(tag, uv, normals);
  std::size_t folded = 0;
  for (std::size_t t = 0; t < n; ++t) {
    double d = 0;
    for (std::size_t j = 0; j < 3; ++j) d += normal_of[3 * t + j] * normals[3 * t + j];
    folded += d < 0;
  }
  return folded;
}

// Surfaces that can fold (every surface but planes: gmsh meshes a plane in an affine parametrization).
std::vector<const ModelSurface*> curved(const std::vector<ModelSurface>& surfaces) {
  std::vector<const ModelSurface*> out;
  for (const ModelSurface& s : surfaces)
    if (BRepAdaptor_Surface(s.face, false).GetType() != GeomAbs_Plane) out.push_back(&s);
  return out;
}

}  // namespace

SurfaceMeshStats mesh_surfaces(const std::vector<ModelSurface>& surfaces) {
  SurfaceMeshStats stats;
  gmsh::option::setNumber("Mesh.Algorithm", kFrontalDelaunay);
  gmsh::option::setNumber("Mesh.AlgorithmSwitchOnFailure", 0);
  for (const ModelSurface& s : surfaces) {
    const bool delaunay = meshed_as_periodic(s.face) && boundary_curves(s.tag) > kFrontalCurveLimit;
    gmsh::model::mesh::setAlgorithm(2, s.tag, delaunay ? kDelaunay : kFrontalDelaunay);
    ++(delaunay ? stats.delaunay : stats.frontal_delaunay);
  }
  generate(2, "surface mesh");

  const std::vector<const ModelSurface*> check = curved(surfaces);
  gmsh::vectorpair folded;
  for (const ModelSurface* s : check)
    if (folded_triangles(s->tag) > 0) {
      folded.push_back({2, s->tag});
      gmsh::model::mesh::setAlgorithm(2, s->tag, kMeshAdapt);
      stats.remeshed.push_back(s->name);
    }
  if (folded.empty()) return stats;
  gmsh::model::mesh::clear(folded);
  gmsh::option::setNumber("Mesh.MeshOnlyEmpty", 1);
  generate(2, "surface mesh of the folded faces with MeshAdapt");
  gmsh::option::setNumber("Mesh.MeshOnlyEmpty", 0);
  for (const auto& [dim, tag] : folded) {
    const std::size_t n = folded_triangles(tag);
    if (n > 0) {
      std::string name;
      for (const ModelSurface& s : surfaces)
        if (s.tag == tag) name = s.name;
      throw MeshError("mesh: the surface mesh of face " + name + " (gmsh surface " + std::to_string(tag) + ") has " +
                      std::to_string(n) + " triangles against the surface normal, also after MeshAdapt");
    }
  }
  return stats;
}

}  // namespace cg::mesh
