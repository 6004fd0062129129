#pragma once
// The checks every acceptance test program runs on the files of its product build (product_build.hpp):
// each file read by a reader that is not ours, compared with what the part is (report.json, blade.brep).
#include <boost/test/unit_test.hpp>

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkIdList.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkXMLPolyDataReader.h>

#include <fstream>

#include "acceptance/product_build.hpp"
#include "export/version.hpp"
#include "brep/step_read_back.hpp"

namespace cg::test {

/// Volumes of the files' solids against blade.brep's: both files hold the exact geometry as decimal text
/// with >= 15 significant digits, so only BRepGProp's integration accuracy (1e-9 relative) and, for
/// IGES, the sewing tolerance (1e-3 mm on edges, closing no gap wider than that) remain: 1e-6 relative.
inline void check_volumes(const std::vector<double>& got, const ProductBuild& b, const char* what) {
  BOOST_TEST_REQUIRE(got.size() == b.volumes.size(), what << ": " << got.size() << " solids, expected " << b.volumes.size());
  for (std::size_t i = 0; i < got.size(); ++i)
    BOOST_TEST(std::abs(got[i] - b.volumes[i]) <= 1e-6 * b.volumes[i], what << " solid " << i << ": " << got[i] << " vs " << b.volumes[i]);
}

/// STEP (XCAF reader, names on): one valid solid per body with the body's name, no free edges, the
/// part's volumes and every face with its feature name.
inline void check_step(const ProductBuild& b) {
  const StepReadBack r = read_step_back(b.file("blade.step"));
  BOOST_TEST_REQUIRE(r.ok);
  std::vector<double> volumes;
  for (const std::string& body : b.bodies) {
    // A part of one body is read back as a product whose shape is that solid: OCCT's reader keeps the
    // solid's name (MANIFOLD_SOLID_BREP('blade', ...)) only for solids below the product's shape.
    const auto it = r.named_solids.find(body);
    const bool single = b.bodies.size() == 1 && r.free_shapes.size() == 1 && count_shapes(r.free_shapes[0], TopAbs_SOLID) == 1;
    BOOST_TEST_REQUIRE((it != r.named_solids.end() || single), "STEP: no solid named " << body);
    if (it == r.named_solids.end())
      BOOST_TEST(read_text(b.file("blade.step")).find("MANIFOLD_SOLID_BREP('" + body + "'") != std::string::npos, body);
    const TopoDS_Shape solid = it != r.named_solids.end() ? it->second : r.free_shapes[0];
    BOOST_TEST(BRepCheck_Analyzer(solid).IsValid(), body);
    BOOST_TEST(free_edges(solid) == 0, body);
    volumes.push_back(volume(solid));
  }
  std::sort(volumes.begin(), volumes.end());
  check_volumes(volumes, b, "STEP");
  BOOST_TEST(r.face_names == b.face_names, "STEP face names: " << r.face_names.size() << " of " << b.faces);
  // Header and product: the schema, millimetres, the product name, this tool as the originating system.
  const std::string text = read_text(b.file("blade.step"));
  BOOST_TEST(text.find(b.step_schema == "AP242" ? "AP242" : "AUTOMOTIVE_DESIGN") != std::string::npos);
  BOOST_TEST(text.find("SI_UNIT(.MILLI.,.METRE.)") != std::string::npos);
  const std::string header = text.substr(0, text.find("ENDSEC;"));
  BOOST_TEST(header.find("FILE_NAME('" + b.product + "'") != std::string::npos, header);
  BOOST_TEST(header.find(std::string("'") + io::kToolName + " " + io::tool_version() + "'") != std::string::npos, header);
  BOOST_TEST(text.find("PRODUCT('" + b.product + "'") != std::string::npos);
  BOOST_TEST(text.find("COLOUR_RGB") != std::string::npos);
}

/// Entity types of an IGES file's directory section (fixed 80-column records, section letter 'D' in
/// column 73; each entry is two records, the type in columns 1-8 of the first).
inline std::map<int, int> iges_entity_types(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::string line;
  std::map<int, int> types;
  int record = 0;
  while (std::getline(in, line))
    if (line.size() >= 73 && line[72] == 'D' && record++ % 2 == 0) ++types[std::stoi(line.substr(0, 8))];
  return types;
}

/// IGES (OCCT's reader, then sewing at 1e-3 mm, as a mesher reading trimmed surfaces does): every face
/// read and valid, one closed shell per body with the part's volume, names (406) and levels read back.
inline void check_iges(const ProductBuild& b) {
  // Geometry only as 144 (one per face) / 142 (its boundary on the surface) / 102 (the boundary as a
  // chain of 126) / 128 (one per face) / 126; the rest is grouping or attributes: 402 (product and
  // body groups), 406 (face names), 314 (colours).
  const std::map<int, int> types = iges_entity_types(b.file("blade.igs"));
  BOOST_TEST((types.count(144) == 1u && types.at(144) == b.faces));
  BOOST_TEST((types.count(128) == 1u && types.at(128) == b.faces));
  for (const auto& [type, n] : types)
    BOOST_TEST((type == 144 || type == 142 || type == 102 || type == 128 || type == 126 || type == 402 || type == 406 ||
                type == 314),
               "unexpected IGES entity type " << type << " (" << n << "x)");
  BOOST_TEST(read_text(b.file("blade.igs")).find(std::string(io::kToolName) + " " + io::tool_version()) != std::string::npos);
  const IgesReadBack r = read_iges_back(b.file("blade.igs"));
  BOOST_TEST_REQUIRE(r.read);
  BOOST_TEST(r.faces == b.faces);
  BOOST_TEST(r.invalid_faces == 0);
  for (const auto& [status, n] : r.invalid_by_status) BOOST_TEST_MESSAGE("IGES invalid faces: " << n << " x " << status);
  BOOST_TEST(r.shells == static_cast<int>(b.bodies.size()));
  BOOST_TEST(r.closed_shells == static_cast<int>(b.bodies.size()));
  BOOST_TEST(r.free_edges == 0);
  check_volumes(r.solid_volumes, b, "IGES");
  BOOST_TEST(r.face_names == b.face_names, "IGES face names: " << r.face_names.size() << " of " << b.faces);
  // One level per feature kind: every face of a kind on the same level, no level shared by two kinds.
  std::map<std::string, std::set<std::string>> levels_of_kind, kinds_on_level;
  for (const auto& [name, level] : r.face_name_layer) {
    BOOST_TEST(!level.empty(), name << " has one level");
    levels_of_kind[brep::feature_kind(name)].insert(level);
    kinds_on_level[level].insert(brep::feature_kind(name));
  }
  BOOST_TEST(levels_of_kind.size() == b.faces_per_kind.size());
  for (const auto& [kind, levels] : levels_of_kind) BOOST_TEST(levels.size() == 1u, kind);
  for (const auto& [level, kinds] : kinds_on_level) BOOST_TEST(kinds.size() == 1u, "level " << level);
}

/// The bound on |V(triangles) - V(B-rep)|: every triangle lies within the linear deflection d of its face
/// (BRepMesh's contract), so the enclosed volume changes by at most d * area. d is the configured
/// stl_deflection, at least 2e-5 of the part's diagonal (export/triangulation.hpp).
inline double tessellation_volume_bound(const ProductBuild& b) {
  const auto& size = b.report.at("solid").at("bbox_mm").at("size");
  const double diagonal = std::hypot(size[0].get<double>(), size[1].get<double>(), size[2].get<double>());
  return std::max(b.stl_deflection, 2e-5 * diagonal) * b.area;
}

/// STL: admesh (Debian) reverses no facet and finds no backwards edge, one part per body; on OCCT's
/// reading of the triangles every directed edge is used once and its opposite once, and the signed
/// volume is the B-rep's within the tessellation bound.
inline void check_stl(const ProductBuild& b) {
  const AdmeshReport a = run_admesh(b.file("blade.stl"));
  BOOST_TEST_REQUIRE(a.ran, a.text);
  BOOST_TEST(a.reversed == 0, a.text);
  BOOST_TEST(a.backwards_edges == 0, a.text);
  BOOST_TEST(a.parts == static_cast<long>(b.bodies.size()), a.text);
  const auto tris = read_stl_triangles(b.file("blade.stl"));
  BOOST_TEST(static_cast<long>(tris.size()) == a.facets);
  const SoupCheck s = check_soup(tris);
  BOOST_TEST(s.unmatched == 0u);
  BOOST_TEST(s.repeated == 0u);
  double brep = 0;
  for (double v : b.volumes) brep += v;
  BOOST_TEST(std::abs(s.signed_volume - brep) <= tessellation_volume_bound(b), "STL " << s.signed_volume << " vs " << brep);
  BOOST_TEST(std::abs(a.volume - s.signed_volume) <= 1e-4 * brep, "admesh " << a.volume << " vs " << s.signed_volume);
}

/// VTK polydata of each body (VTK's XML reader): closed and outward as the STL, and every point normal
/// on the outward side of its triangles (dot product with the winding normal > 0).
inline void check_vtk(const ProductBuild& b) {
  double total = 0;
  for (const std::string& body : b.bodies) {
    auto reader = vtkSmartPointer<vtkXMLPolyDataReader>::New();
    reader->SetFileName(b.file("blade_" + body + ".vtp").string().c_str());
    reader->Update();
    vtkPolyData* pd = reader->GetOutput();
    BOOST_TEST_REQUIRE(pd->GetNumberOfPolys() > 0, body);
    vtkDataArray* normals = pd->GetPointData()->GetNormals();
    BOOST_TEST_REQUIRE(normals != nullptr, body);
    std::vector<std::array<Eigen::Vector3d, 3>> tris;
    std::size_t inward = 0;
    auto ids = vtkSmartPointer<vtkIdList>::New();
    vtkCellArray* polys = pd->GetPolys();
    polys->InitTraversal();
    while (polys->GetNextCell(ids)) {
      BOOST_TEST_REQUIRE(ids->GetNumberOfIds() == 3);
      std::array<Eigen::Vector3d, 3> t;
      Eigen::Vector3d n = Eigen::Vector3d::Zero();
      for (int k = 0; k < 3; ++k) {
        double p[3], q[3];
        pd->GetPoint(ids->GetId(k), p);
        normals->GetTuple(ids->GetId(k), q);
        t[static_cast<std::size_t>(k)] = Eigen::Vector3d(p[0], p[1], p[2]);
        n += Eigen::Vector3d(q[0], q[1], q[2]);
      }
      if ((t[1] - t[0]).cross(t[2] - t[0]).dot(n) <= 0) ++inward;
      tris.push_back(t);
    }
    const SoupCheck s = check_soup(tris);
    BOOST_TEST(s.unmatched == 0u, body);
    BOOST_TEST(s.repeated == 0u, body);
    BOOST_TEST(s.signed_volume > 0, body);
    BOOST_TEST(inward == 0u, body << ": " << inward << " of " << tris.size() << " triangles with point normals against their winding");
    total += s.signed_volume;
  }
  double brep = 0;
  for (double v : b.volumes) brep += v;
  BOOST_TEST(std::abs(total - brep) <= tessellation_volume_bound(b), "VTK " << total << " vs " << brep);
}

}  // namespace cg::test
