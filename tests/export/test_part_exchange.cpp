// STEP, IGES and BREP of a cooled part (the built-in example blade with two chambers, four film holes
// and an insert body, made in the test): read back with OCCT they give the same solids, face counts and
// volumes (1e-6 relative: the files store the exact geometry as decimal text with >= 15 significant
// digits, so only BRepGProp's integration accuracy 1e-9 remains); face and body names read back through
// XCAF match the features; the STEP header names the product and the tool; the IGES directory holds
// only 144/142/128/126 geometry, one 144 per face, on one level per feature kind.
#define BOOST_TEST_MODULE part_exchange
#include <boost/test/unit_test.hpp>

#include <BRepTools.hxx>
#include <BRep_Builder.hxx>
#include <IGESCAFControl_Reader.hxx>
#include <IGESControl_Controller.hxx>
#include <IGESControl_Reader.hxx>
#include <Interface_Static.hxx>
#include <STEPCAFControl_Controller.hxx>
#include <STEPCAFControl_Reader.hxx>
#include <STEPControl_Reader.hxx>
#include <TDataStd_Name.hxx>
#include <TDocStd_Document.hxx>
#include <XCAFApp_Application.hxx>
#include <XCAFDoc_DocumentTool.hxx>
#include <XCAFDoc_ShapeTool.hxx>

#include <map>
#include <set>

#include "brep/temp_files.hpp"
#include "export/brep_writer.hpp"
#include "export/cooled_part.hpp"
#include "export/feature_style.hpp"
#include "export/iges_writer.hpp"
#include "export/step_writer.hpp"
#include "export/version.hpp"

namespace fs = std::filesystem;
using namespace cg;

namespace {

const test::CooledPart& part() {
  static const test::CooledPart p = test::cooled_example();
  return p;
}

int count(const TopoDS_Shape& s, TopAbs_ShapeEnum t) {
  int n = 0;
  for (TopExp_Explorer e(s, t); e.More(); e.Next()) ++n;
  return n;
}

std::vector<double> solid_volumes(const TopoDS_Shape& s) {
  std::vector<double> v;
  for (TopExp_Explorer e(s, TopAbs_SOLID); e.More(); e.Next()) v.push_back(test::volume_of(e.Current()));
  std::sort(v.begin(), v.end());
  return v;
}

// Same solids (count, sorted volumes within 1e-6 relative) and same face count as the part.
void check_same_geometry(const TopoDS_Shape& back, const char* what) {
  std::vector<double> expected;
  int faces = 0;
  for (const auto& b : part().part) {
    expected.push_back(test::volume_of(b.geometry.shape));
    faces += static_cast<int>(b.geometry.faces.size());
  }
  std::sort(expected.begin(), expected.end());
  const auto got = solid_volumes(back);
  BOOST_TEST_REQUIRE(got.size() == expected.size(), what);
  for (std::size_t i = 0; i < got.size(); ++i)
    BOOST_TEST(std::abs(got[i] - expected[i]) <= 1e-6 * expected[i], what << " solid " << i << ": " << got[i] << " vs " << expected[i]);
  BOOST_TEST(count(back, TopAbs_FACE) == faces, what);
}

std::multiset<std::string> expected_face_names() {
  std::multiset<std::string> n;
  for (const auto& b : part().part)
    for (const auto& f : b.geometry.faces) n.insert(f.name);
  return n;
}

// Names on the sub-shape labels of the free shapes of an XCAF document: faces and solids separately.
void xcaf_names(const Handle(TDocStd_Document)& doc, std::multiset<std::string>& faces, std::multiset<std::string>& solids,
                std::set<std::string>& products) {
  const Handle(XCAFDoc_ShapeTool) tool = XCAFDoc_DocumentTool::ShapeTool(doc->Main());
  TDF_LabelSequence free_shapes;
  tool->GetFreeShapes(free_shapes);
  for (const TDF_Label& l : free_shapes) {
    Handle(TDataStd_Name) pn;
    if (l.FindAttribute(TDataStd_Name::GetID(), pn)) products.insert(TCollection_AsciiString(pn->Get()).ToCString());
    TDF_LabelSequence subs;
    XCAFDoc_ShapeTool::GetSubShapes(l, subs);
    for (const TDF_Label& s : subs) {
      Handle(TDataStd_Name) n;
      if (!s.FindAttribute(TDataStd_Name::GetID(), n)) continue;
      const std::string name = TCollection_AsciiString(n->Get()).ToCString();
      const TopAbs_ShapeEnum type = XCAFDoc_ShapeTool::GetShape(s).ShapeType();
      if (type == TopAbs_FACE) faces.insert(name);
      if (type == TopAbs_SOLID) solids.insert(name);
    }
  }
}

}  // namespace

BOOST_AUTO_TEST_CASE(test_part_is_what_it_claims) {
  const auto& p = part();
  BOOST_TEST_REQUIRE(p.part.size() == 2u);
  const auto counts = brep::count_face_names(p.part[0].geometry);
  for (const char* n : {"blade_wall", "hub", "casing", "chamber_1_wall", "chamber_2_wall", "chamber_1_end", "film_row_1_hole_004"})
    BOOST_TEST(counts.count(n) == 1u, n);
  BOOST_TEST(p.removed_volume > 0);
}

BOOST_AUTO_TEST_CASE(step_round_trip_with_names_and_header) {
  for (io::StepSchema schema : {io::StepSchema::AP242, io::StepSchema::AP214}) {
    test::TempDir dir(std::string("xstep_") + io::step_schema_name(schema));
    const fs::path file = dir.path / "blade.step";
    io::write_step(file, part().part, {schema, "cooled_rotor"});
    BOOST_TEST(dir.entries() == std::vector<std::string>{"blade.step"});

    STEPControl_Reader reader;
    BOOST_TEST_REQUIRE(reader.ReadFile(file.string().c_str()) == IFSelect_RetDone);
    BOOST_TEST_REQUIRE(reader.TransferRoots() >= 1);
    check_same_geometry(reader.OneShape(), io::step_schema_name(schema));

    const std::string text = test::read_text(file);
    BOOST_TEST(text.find(schema == io::StepSchema::AP242 ? "AP242" : "AUTOMOTIVE_DESIGN") != std::string::npos);
    BOOST_TEST(text.find("SI_UNIT(.MILLI.,.METRE.)") != std::string::npos);
    const std::string header = text.substr(0, text.find("ENDSEC;"));
    BOOST_TEST(header.find("FILE_NAME('cooled_rotor'") != std::string::npos, header);
    BOOST_TEST(header.find(std::string("'") + io::kToolName + " " + io::tool_version() + "'") != std::string::npos, header);
    BOOST_TEST(text.find("PRODUCT('cooled_rotor'") != std::string::npos);
    BOOST_TEST(text.find("COLOUR_RGB") != std::string::npos);

    STEPCAFControl_Controller::Init();
    Interface_Static::SetIVal("read.stepcaf.subshapes.name", 1);
    Handle(TDocStd_Application) app = XCAFApp_Application::GetApplication();
    Handle(TDocStd_Document) doc;
    app->NewDocument("MDTV-XCAF", doc);
    STEPCAFControl_Reader xr;
    xr.SetNameMode(true);
    BOOST_TEST_REQUIRE(xr.ReadFile(file.string().c_str()) == IFSelect_RetDone);
    BOOST_TEST_REQUIRE(xr.Transfer(doc));
    std::multiset<std::string> faces, solids;
    std::set<std::string> products;
    xcaf_names(doc, faces, solids, products);
    app->Close(doc);
    BOOST_TEST(faces == expected_face_names());
    BOOST_TEST(solids == (std::multiset<std::string>{"blade", "insert_1"}));
    BOOST_TEST(products.count("cooled_rotor") == 1u);
  }
}

BOOST_AUTO_TEST_CASE(brep_round_trip) {
  test::TempDir dir("xbrep");
  const fs::path file = dir.path / "blade.brep";
  io::write_brep(file, part().part);
  TopoDS_Shape back;
  BRep_Builder b;
  BOOST_TEST_REQUIRE(BRepTools::Read(back, file.string().c_str(), b));
  check_same_geometry(back, "BREP");
}

// Entity types of the IGES directory entry section (fixed 80-column records, section letter 'D' in
// column 73; each entry is two records, the type in columns 1-8 of the first, the level in 33-40).
struct IgesEntity {
  int type = 0, level = 0;
};
std::vector<IgesEntity> iges_directory(const fs::path& file) {
  std::ifstream in(file);
  std::string line;
  std::vector<IgesEntity> out;
  int record = 0;
  while (std::getline(in, line)) {
    if (line.size() < 73 || line[72] != 'D') continue;
    if (record++ % 2 == 0) out.push_back({std::stoi(line.substr(0, 8)), std::stoi(line.substr(32, 8))});
  }
  return out;
}

BOOST_AUTO_TEST_CASE(iges_trimmed_nurbs_only_named_by_level) {
  test::TempDir dir("xiges");
  const fs::path file = dir.path / "blade.igs";
  io::write_iges(file, part().part, {"cooled_rotor"});
  BOOST_TEST(dir.entries() == std::vector<std::string>{"blade.igs"});

  const auto entities = iges_directory(file);
  std::map<int, int> types;
  for (const auto& e : entities) ++types[e.type];
  int faces = 0;
  for (const auto& b : part().part) faces += static_cast<int>(b.geometry.faces.size());
  BOOST_TEST(types[144] == faces);
  BOOST_TEST(types[128] == faces);  // one rational B-spline surface under each trimmed surface
  BOOST_TEST(types[126] > 0);
  // Geometry only as 144 / 142 (its boundary on the surface) / 102 (the boundary as a chain of 126) /
  // 128 / 126; everything else is grouping or attributes: 402 (the product and body groups), 406
  // (face names), 314 (colours).
  for (const auto& [type, n] : types)
    BOOST_TEST((type == 144 || type == 142 || type == 102 || type == 128 || type == 126 || type == 402 || type == 406 ||
                type == 314),
               "unexpected IGES entity type " << type << " (" << n << "x)");
  // Trimmed surfaces lie on the level of their kind: kind id + 1, every kind used.
  const io::FeatureTable table = io::feature_table(part().part);
  std::map<int, int> faces_on_level, faces_of_kind;
  for (const auto& e : entities)
    if (e.type == 144) ++faces_on_level[e.level];
  for (const auto& b : part().part)
    for (const auto& f : b.geometry.faces) ++faces_of_kind[table.kind_id(f.name) + 1];
  BOOST_TEST(faces_on_level == faces_of_kind);
  const std::string text = test::read_text(file);
  BOOST_TEST(text.find(std::string(io::kToolName) + " " + io::tool_version()) != std::string::npos);

  IGESControl_Controller::Init();
  IGESControl_Reader reader;
  BOOST_TEST_REQUIRE(reader.ReadFile(file.string().c_str()) == IFSelect_RetDone);
  reader.TransferRoots();
  const TopoDS_Shape faces_back = reader.OneShape();
  BOOST_TEST(count(faces_back, TopAbs_FACE) == faces);
}
