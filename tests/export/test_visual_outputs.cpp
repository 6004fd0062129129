// STL, VTK, preview and section drawing of cooled test parts.
//  - STL: binary layout (84 + 50 n bytes) with the triangle count the writer reports.
//  - VTK: the .vtp pieces read back with VTK have every triangle tagged with a valid feature id and the
//    name tables; the .vtm names every piece.
//  - Sections of the C3X vane (planar cuts, features/passages/span_sections.hpp): passage areas against the
//    analytic area of the cut of a straight cylinder by a plane, pi r^2 / |d.n| (minus the insert's
//    ring), to 1e-6 relative (the curves are traced onto the faces to 1e-11 mm and integrated exactly;
//    measured 2e-7: the boolean's edges lie off the faces within their tolerance), with the film holes
//    into chamber 1 closed over.
//  - sections.svg and preview.png exist and are not blank: drawing extent = chord x scale; the PNG has
//    a plausible share of non-background pixels spread over the picture, and pixels in the chamber
//    colour (the cooling shows through the semi-transparent wall). Without any X server the PNG test is
//    skipped with a message.
#define BOOST_TEST_MODULE visual_outputs
#include <boost/test/unit_test.hpp>

#include <vtkCellData.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkIntArray.h>
#include <vtkPNGReader.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkXMLPolyDataReader.h>

#include <BRepAdaptor_Curve.hxx>
#include <BRepAlgoAPI_Section.hxx>
#include <BRepBuilderAPI_MakeFace.hxx>
#include <GCPnts_TangentialDeflection.hxx>
#include <Geom_BSplineCurve.hxx>
#include <Geom_SurfaceOfRevolution.hxx>
#include <TopExp_Explorer.hxx>

#include <regex>
#include <set>

#include "adaptors/occt_convert.hpp"

#include "brep/temp_files.hpp"
#include "export/atomic_file.hpp"
#include "export/cooled_part.hpp"
#include "export/preview.hpp"
#include "features/passages/span_sections.hpp"
#include "export/sections_svg.hpp"
#include "export/stl_writer.hpp"
#include "export/triangulation.hpp"
#include "export/vtk_writer.hpp"

namespace fs = std::filesystem;
using namespace cg;

namespace {

const test::CooledPart& example() {
  static const test::CooledPart p = test::cooled_example();
  return p;
}

}  // namespace

BOOST_AUTO_TEST_CASE(stl_binary) {
  test::TempDir dir("vstl");
  const std::size_t n = io::write_stl(dir.path / "blade.stl", example().part, {0.01, 0.35});
  BOOST_TEST(n > 1000u);
  BOOST_TEST(fs::file_size(dir.path / "blade.stl") == 84 + 50 * n);
  BOOST_CHECK_THROW(io::write_stl(dir.path / "bad.stl", example().part, {0.0, 0.35}), io::ExportError);
}

BOOST_AUTO_TEST_CASE(vtk_files_with_feature_ids) {
  test::TempDir dir("vvtk");
  const io::PartTriangles t = io::triangulate_part(example().part);
  const io::VtkFiles files = io::write_vtk(dir.path, "blade", example().part, t);
  BOOST_TEST_REQUIRE(files.pieces.size() == 2u);
  const std::string vtm = test::read_text(files.multiblock);
  BOOST_TEST(vtm.find("name=\"insert_1\" file=\"blade_insert_1.vtp\"") != std::string::npos, vtm);
  vtkIdType cells = 0;
  for (std::size_t b = 0; b < 2; ++b) {
    auto r = vtkSmartPointer<vtkXMLPolyDataReader>::New();
    r->SetFileName(files.pieces[b].string().c_str());
    r->Update();
    vtkPolyData* pd = r->GetOutput();
    BOOST_TEST_REQUIRE(pd->GetNumberOfCells() > 0);
    cells += pd->GetNumberOfCells();
    auto* fid = vtkIntArray::SafeDownCast(pd->GetCellData()->GetArray("feature_id"));
    auto* nid = vtkIntArray::SafeDownCast(pd->GetCellData()->GetArray("face_name_id"));
    auto* kinds = vtkStringArray::SafeDownCast(pd->GetFieldData()->GetAbstractArray("feature_kinds"));
    auto* names = vtkStringArray::SafeDownCast(pd->GetFieldData()->GetAbstractArray("face_names"));
    BOOST_TEST_REQUIRE((fid && nid && kinds && names));
    BOOST_TEST(kinds->GetNumberOfValues() == static_cast<vtkIdType>(t.table.kinds.size()));
    std::set<std::string> seen;
    for (vtkIdType c = 0; c < pd->GetNumberOfCells(); ++c) {
      const int k = fid->GetValue(c), n = nid->GetValue(c);
      BOOST_TEST_REQUIRE((k >= 0 && k < kinds->GetNumberOfValues() && n >= 0 && n < names->GetNumberOfValues()));
      BOOST_TEST_REQUIRE(brep::feature_kind(names->GetValue(n)) == kinds->GetValue(k));
      seen.insert(names->GetValue(n));
    }
    if (b == 0) BOOST_TEST(seen.count("film_row_1_hole_002") == 1u);
    if (b == 1) BOOST_TEST(seen == std::set<std::string>{"insert_1"});
  }
  BOOST_TEST(cells == static_cast<vtkIdType>(t.triangles.size()));
}

BOOST_AUTO_TEST_CASE(c3x_passage_areas_match_the_cylinders) {
  test::CooledPartOptions o;
  o.holes = 2;
  const test::CooledPart c3x = test::cooled_c3x(o);
  const auto surfaces = features::span_surfaces(c3x.model, {0.3, 0.6});
  const auto cuts = features::span_sections(c3x.part, surfaces);
  BOOST_TEST_REQUIRE(cuts.size() == 2u);
  // The fixture's chambers: recover axis and radius from the tool faces is not possible after the cut,
  // so rebuild them the same way (make_cooled_part is deterministic) from a part without holes.
  for (const auto& cut : cuts) {
    BOOST_TEST(cut.unclosed_openings == 0);
    BOOST_TEST_REQUIRE(cut.passages.size() == 2u);
    BOOST_TEST(cut.passages[0].name == "chamber_1");  // the passage of the faces chamber_1_wall
    BOOST_TEST(cut.passages[1].name == "chamber_2");
    BOOST_TEST(std::abs(cut.chord - 144.93) < 2.0);  // the C3X true chord (NASA CR-168015), +- LE/TE rounding
  }
  // Analytic: the plane z = const cuts the cylinder (axis d, radius r) in an ellipse of area pi r^2 / |d_z|.
  for (std::size_t k = 0; k < 2; ++k) {
    const auto& p = c3x.chamber_axes[k];
    const double dz = std::abs((p.second - p.first).normalized().z());
    const double r = c3x.chamber_radii[k];
    for (const auto& cut : cuts) {
      double expected = test::kPi * r * r / dz;
      const double at = (cut.span * 144.93 - p.first.z()) / (p.second.z() - p.first.z());  // along the chamber
      if (k == 1 && at > 0.25 && at < 0.7) expected -= test::kPi * (0.49 - 0.25) * r * r / dz;  // the insert ring
      BOOST_TEST(std::abs(cut.passages[k].area - expected) <= 1e-6 * expected,
                 "span " << cut.span << " chamber " << k + 1 << ": " << cut.passages[k].area << " vs " << expected);
      BOOST_TEST_MESSAGE("span " << cut.span << " chamber " << k + 1 << ": relative area error "
                                 << (cut.passages[k].area - expected) / expected);
    }
  }
}

namespace {

// The section the plain way: BRepAlgoAPI_Section of the whole blade body with the surface of revolution
// over +-90 deg, its edges drawn at 0.005 mm as (x, r dtheta) points.
std::vector<features::SectionCurve> full_section(const brep::NamedShape& body, const features::SpanSurface& r) {
  const Handle(Geom2d_BSplineCurve) c2 = occt::to_occt(*r.meridional);
  TColgp_Array1OfPnt poles(1, c2->NbPoles());
  TColStd_Array1OfReal weights(1, c2->NbPoles()), knots(1, c2->NbKnots());
  TColStd_Array1OfInteger mults(1, c2->NbKnots());
  for (int i = 1; i <= c2->NbPoles(); ++i) poles(i) = gp_Pnt(c2->Pole(i).X(), c2->Pole(i).Y(), 0), weights(i) = c2->Weight(i);
  c2->Knots(knots);
  c2->Multiplicities(mults);
  const Handle(Geom_BSplineCurve) c3 = new Geom_BSplineCurve(poles, weights, knots, mults, c2->Degree());
  const TopoDS_Face tool = BRepBuilderAPI_MakeFace(new Geom_SurfaceOfRevolution(c3, gp::OX()), r.theta_centre - test::kPi / 2,
                                                   r.theta_centre + test::kPi / 2, c3->FirstParameter(), c3->LastParameter(), 1e-7);
  BRepAlgoAPI_Section sec(body.shape, tool, false);
  sec.Approximation(true);
  sec.Build();
  BOOST_TEST_REQUIRE(sec.IsDone());
  std::vector<features::SectionCurve> curves;
  for (TopExp_Explorer e(sec.Shape(), TopAbs_EDGE); e.More(); e.Next()) {
    BRepAdaptor_Curve curve(TopoDS::Edge(e.Current()));
    GCPnts_TangentialDeflection d(curve, 0.05, 0.005, 4);
    features::SectionCurve c;
    for (int k = 1; k <= d.NbPoints(); ++k) {
      const gp_Pnt q = d.Value(k);
      c.points.emplace_back(q.X(), std::hypot(q.Y(), q.Z()) * std::remainder(std::atan2(q.Z(), q.Y()) - r.theta_centre, 2 * test::kPi));
    }
    curves.push_back(std::move(c));
  }
  return curves;
}

double distance_to_polylines(const Eigen::Vector2d& p, const std::vector<features::SectionCurve>& curves) {
  double best = HUGE_VAL;
  for (const features::SectionCurve& c : curves)
    for (std::size_t k = 0; k + 1 < c.points.size(); ++k) {
      const Eigen::Vector2d a = c.points[k], ab = c.points[k + 1] - a;
      const double t = ab.squaredNorm() > 0 ? std::clamp((p - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0) : 0.0;
      best = std::min(best, (p - a - t * ab).norm());
    }
  return best;
}

}  // namespace

// span_sections traces the curves on the faces whose boxes can meet the surface of revolution: the same
// curves as OCCT's plain section of the whole body. Every point of either lies within 0.01 mm of the
// other's polylines (OCCT's drawn at 0.005 mm, ours through points on the curves, chords within
// 0.006 mm), and every opening crossing the cut is closed.
BOOST_AUTO_TEST_CASE(prefiltered_sections_match_the_full_section) {
  const auto surfaces = features::span_surfaces(example().model, {0.2, 0.5, 0.8});
  const auto cuts = features::span_sections(example().part, surfaces);
  BOOST_TEST_REQUIRE(cuts.size() == 3u);
  for (std::size_t i = 0; i < cuts.size(); ++i) {
    BOOST_TEST_REQUIRE((surfaces[i].kind == features::SpanSurfaceKind::Revolved));  // the example is a meridional blade
    BOOST_TEST(cuts[i].unclosed_openings == 0);
    const std::vector<features::SectionCurve> full = full_section(example().part[0].geometry, surfaces[i]);
    std::vector<features::SectionCurve> blade;
    for (const features::SectionCurve& c : cuts[i].curves)
      if (c.body == 0) blade.push_back(c);
    BOOST_TEST_REQUIRE(full.size() > 3u);
    double worst_full = 0, worst_new = 0;
    for (const features::SectionCurve& c : full)
      for (const Eigen::Vector2d& p : c.points) worst_full = std::max(worst_full, distance_to_polylines(p, blade));
    for (const features::SectionCurve& c : blade)
      for (const Eigen::Vector2d& p : c.points) worst_new = std::max(worst_new, distance_to_polylines(p, full));
    BOOST_TEST(worst_full <= 0.01, "span " << cuts[i].span << ": a point of the full section is " << worst_full << " mm away");
    BOOST_TEST(worst_new <= 0.01, "span " << cuts[i].span << ": a point of the new section is " << worst_new << " mm away");
  }
}

BOOST_AUTO_TEST_CASE(sections_svg_shows_the_sections) {
  const auto surfaces = features::span_surfaces(example().model, {0.1, 0.3, 0.6, 0.9});
  const auto cuts = features::span_sections(example().part, surfaces);
  BOOST_TEST_REQUIRE(cuts.size() == 4u);
  for (const auto& c : cuts) {
    BOOST_TEST(c.unclosed_openings == 0);
    BOOST_TEST(c.chord > 25.0);  // the example's chord is about 36 mm at every span
    BOOST_TEST(c.chord < 45.0);
    BOOST_TEST(c.metal_area > 0);
  }
  BOOST_TEST(cuts[1].passages.size() == 2u);
  test::TempDir dir("vsvg");
  const fs::path file = dir.path / "sections.svg";
  io::write_sections_svg(file, cuts, "hpt_rotor <cooled>");
  const std::string svg = test::read_text(file);
  BOOST_TEST(svg.find("hpt_rotor &lt;cooled&gt;") != std::string::npos);
  BOOST_TEST(svg.find(io::hex_colour(io::kind_colour("chamber"))) != std::string::npos);
  // Extent of the stroked outline paths of the first panel: chord x scale within 2 %.
  const std::smatch scale_m = [&] {
    std::smatch m;
    std::regex_search(svg, m, std::regex("scale ([0-9.]+) px/mm"));
    return m;
  }();
  BOOST_TEST_REQUIRE(scale_m.size() == 2u);
  const double scale = std::stod(scale_m[1]);
  const std::string first = svg.substr(svg.find("<g>"), svg.find("</g>") - svg.find("<g>"));
  double xmin = 1e9, xmax = -1e9, ymin = 1e9, ymax = -1e9;
  const std::regex pt("[ML]([0-9.]+),([0-9.]+)");
  for (auto it = std::sregex_iterator(first.begin(), first.end(), pt); it != std::sregex_iterator(); ++it) {
    const double x = std::stod((*it)[1]), y = std::stod((*it)[2]);
    xmin = std::min(xmin, x), xmax = std::max(xmax, x), ymin = std::min(ymin, y), ymax = std::max(ymax, y);
  }
  const double extent = std::hypot(xmax - xmin, ymax - ymin);
  BOOST_TEST(extent >= cuts[0].chord * scale * 0.98);
  BOOST_TEST(extent <= cuts[0].chord * scale * 1.5);  // the box diagonal exceeds the chord by the thickness
  BOOST_TEST(xmax - xmin > 200);                      // a drawing, not a dot
}

BOOST_AUTO_TEST_CASE(preview_png_shows_the_cooling) {
  test::TempDir dir("vpng");
  const fs::path file = dir.path / "preview.png";
  const io::PartTriangles t = io::triangulate_part(example().part, {0.02, 0.4});
  const io::PreviewResult r = io::write_preview(file, t, {640, 480, 0.22, "test", Eigen::Vector3d::Zero()});
  if (!r.written) {
    BOOST_TEST_MESSAGE("SKIPPED preview test: " << r.message);
    BOOST_TEST(r.message.find("skipped") != std::string::npos);
    return;
  }
  auto reader = vtkSmartPointer<vtkPNGReader>::New();
  reader->SetFileName(file.string().c_str());
  reader->Update();
  vtkImageData* img = reader->GetOutput();
  int dims[3];
  img->GetDimensions(dims);
  BOOST_TEST_REQUIRE(dims[0] == 640);
  BOOST_TEST_REQUIRE(dims[1] == 480);
  const int comps = img->GetNumberOfScalarComponents();
  long drawn = 0, blue = 0;
  int x0 = dims[0], x1 = -1, y0 = dims[1], y1 = -1;
  for (int y = 0; y < dims[1]; ++y)
    for (int x = 0; x < dims[0]; ++x) {
      const auto* p = static_cast<unsigned char*>(img->GetScalarPointer(x, y, 0));
      if (p[0] > 245 && p[1] > 245 && p[2] > 245) continue;
      if (y < 60 || x < 5) continue;  // title and legend text
      ++drawn;
      x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
      if (p[2] > p[0] + 40 && p[2] > p[1] + 10) ++blue;  // chamber blue
    }
  (void)comps;
  const double share = static_cast<double>(drawn) / (dims[0] * dims[1]);
  BOOST_TEST(share > 0.03, "non-background share " << share);
  BOOST_TEST(share < 0.8, "non-background share " << share);
  BOOST_TEST(x1 - x0 > dims[0] / 5);
  BOOST_TEST(y1 - y0 > dims[1] / 3);
  BOOST_TEST(blue > 200, blue << " chamber-coloured pixels");
}
