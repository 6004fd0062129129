// blade.import formats "step" and "iges": our own uncooled blades (the built-in rotor, the C3X vane as a
// straight cascade) written as CAD by OCCT's writers (the product's named STEP; a STEP re-split by
// ShapeUpgrade and written by a plain STEPControl_Writer, so it carries no face names and a different
// face split; IGES trimmed surfaces, i.e. loose faces; the wall surface alone, past hub and casing),
// imported again: the ORIGINAL wall at points between the import's cuts lies within 0.01 mm of the
// imported wall; a cooled C3X vane on its STEP, geomTurbo and section-table imports is valid with the same
// feature names as the original's; hostile files are refused by
// `coolinggen validate` with one line naming blade.import.file, exit 2.
#define BOOST_TEST_MODULE cli_import_cad
#include <boost/test/unit_test.hpp>

#include <BRepBuilderAPI_MakeFace.hxx>
#include <BRepBuilderAPI_MakeVertex.hxx>
#include <Precision.hxx>
#include <BRepGProp.hxx>
#include <GProp_GProps.hxx>
#include <IGESControl_Writer.hxx>
#include <Interface_Static.hxx>
#include <STEPControl_Writer.hxx>
#include <ShapeUpgrade_ShapeDivideArea.hxx>
#include <TopExp_Explorer.hxx>
#include <BRepBuilderAPI_Transform.hxx>
#include <BRep_Builder.hxx>
#include <TopoDS.hxx>
#include <TopoDS_Compound.hxx>
#include <TopoDS_Vertex.hxx>

#include <chrono>
#include <fstream>
#include <set>

#include "adaptors/occt_convert.hpp"
#include "acceptance/readers.hpp"
#include "brep/step_read_back.hpp"
#include "cli/run_cli.hpp"
#include "cli/section_tables.hpp"
#include "src/blade_import/geomturbo_writer.hpp"
#include "export/step_writer.hpp"
#include "src/algo/project_point_surface.hpp"
#include "src/brep/blade_solid.hpp"
#include "src/config/builtin_example.hpp"
#include "src/config/config.hpp"
#include "src/pipeline/report.hpp"

using namespace cg;
namespace fs = std::filesystem;

namespace {

const fs::path kExamples = fs::path(COOLINGGEN_SOURCE_DIR) / "data/examples";

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

int face_count(const TopoDS_Shape& s) {
  int n = 0;
  for (TopExp_Explorer e(s, TopAbs_FACE); e.More(); e.Next()) ++n;
  return n;
}

enum class As { NamedStep, SplitStep, Iges, WallSurface, MetreStep };

// The uncooled blade solid of `model` written to `file` as `as` says (WallSurface: only the wall's
// surface as one face, over-built past hub and casing as aero tools give it; MetreStep: a plain STEP
// whose length unit is the metre); returns the faces written.
int write_blade(const blade::BladeModel& model, As as, const fs::path& file) {
  if (as == As::WallSurface) {
    STEPControl_Writer w;
    const TopoDS_Face face = BRepBuilderAPI_MakeFace(occt::to_occt(model.surface), Precision::Confusion()).Face();
    BOOST_TEST_REQUIRE(w.Transfer(face, STEPControl_AsIs) == IFSelect_RetDone);
    BOOST_TEST_REQUIRE(w.Write(file.c_str()) == IFSelect_RetDone);
    return 1;
  }
  const brep::BladeSolid solid = brep::build_blade_solid(model);
  if (as == As::NamedStep) {
    io::write_step(file, solid.solid, solid.faces);
    return face_count(solid.solid);
  }
  if (as == As::MetreStep) {
    // OCCT 7.6's writer labels the numbers with write.step.unit without converting them (a 30 mm box
    // came back 30 m long), so the solid is scaled to metres first, as a CAD system in metres has it.
    gp_Trsf to_metres;
    to_metres.SetScale(gp_Pnt(0, 0, 0), 1e-3);
    const TopoDS_Shape metres = BRepBuilderAPI_Transform(solid.solid, to_metres, true).Shape();
    STEPControl_Writer w;  // (its first construction loads the defaults)
    Interface_Static::SetCVal("write.step.unit", "M");  // global: set back below
    const bool done = w.Transfer(metres, STEPControl_AsIs) == IFSelect_RetDone && w.Write(file.c_str()) == IFSelect_RetDone;
    Interface_Static::SetCVal("write.step.unit", "MM");
    BOOST_TEST_REQUIRE(done);
    const std::string text = test::read_text(file);
    BOOST_TEST_REQUIRE((text.find("SI_UNIT($,.METRE.)") != std::string::npos), "the file's length unit is the metre");
    return face_count(solid.solid);
  }
  if (as == As::Iges) {
    IGESControl_Writer w("MM", 0);  // faces mode: trimmed surfaces, no shared edges
    BOOST_TEST_REQUIRE(w.AddShape(solid.solid));
    w.ComputeModel();
    BOOST_TEST_REQUIRE(w.Write(file.c_str()));
    return face_count(solid.solid);
  }
  GProp_GProps props;
  BRepGProp::SurfaceProperties(solid.solid, props);
  ShapeUpgrade_ShapeDivideArea split(solid.solid);
  split.MaxArea() = props.Mass() / 12;
  BOOST_TEST_REQUIRE(split.Perform());
  const TopoDS_Shape shape = split.Result();
  STEPControl_Writer w;  // plain: no names
  BOOST_TEST_REQUIRE(w.Transfer(shape, STEPControl_AsIs) == IFSelect_RetDone);
  BOOST_TEST_REQUIRE(w.Write(file.c_str()) == IFSelect_RetDone);
  return face_count(shape);
}

// The config with its blade replaced by blade.import of `file` (its flow path kept).
nlohmann::json import_config(nlohmann::json c, const char* format, const fs::path& file) {
  c.erase("sections");
  c["blade"]["import"] = {{"format", format}, {"file", file.string()}};
  return c;
}

struct Figures {
  double max_between = 0, max_record = 0, max_on_faces = 0;
  double import_s = 0, parametric_s = 0;
};

// Writes the original's blade as `as`, imports it (no cooling) and measures: points of the ORIGINAL wall
// half-way between the import's cuts and between their chordwise samples, projected onto the imported
// wall.
Figures round_trip(const config::Config& original_config, As as, const std::string& tag) {
  Figures f;
  auto t0 = std::chrono::steady_clock::now();
  const blade::BladeModel original = config::build_model(original_config);
  f.parametric_s = seconds_since(t0);
  test::TempDir dir("import_cad_" + tag);
  const fs::path file = dir.path / (as == As::Iges ? "blade.igs" : "blade.step");
  const int faces = write_blade(original, as, file);
  if (as == As::SplitStep) BOOST_TEST(faces >= 8, tag << ": the split solid has " << faces << " faces");
  nlohmann::json doc = import_config(original_config.source, as == As::Iges ? "iges" : "step", file);
  doc.erase("cooling");
  doc.erase("coolant");
  t0 = std::chrono::steady_clock::now();
  const config::Config ci = config::parse_config(doc, kExamples, tag);
  const blade::BladeModel imported = config::build_model(ci);
  f.import_s = seconds_since(t0);
  BOOST_TEST_REQUIRE(imported.imported.has_value());
  f.max_record = imported.imported->overall.max;
  for (const auto& s : imported.imported->sections) f.max_on_faces = std::max(f.max_on_faces, s.on_faces.max);
  BOOST_TEST(imported.imported->sections.front().on_faces.points > 0);
  SurfaceProjector proj(imported.surface);
  const int cuts = imported.imported->cuts;
  for (int k = 0; k + 1 < cuts; ++k)
    for (double w : {0.25, 0.5, 0.75}) {
      const double v = (k + w) / (cuts - 1);
      for (int i = 0; i < 97; ++i)
        f.max_between = std::max(f.max_between, proj.project(original.surface.point((i + 0.37) / 97, v)).distance);
    }
  BOOST_TEST_MESSAGE(tag << ": " << faces << " faces; original wall between the cuts -> imported wall " << f.max_between
                         << " mm; import's record " << f.max_record << " mm (on the input faces " << f.max_on_faces
                         << " mm); import " << f.import_s << " s / parametric " << f.parametric_s << " s = "
                         << f.import_s / f.parametric_s);
  BOOST_TEST(f.max_between <= 0.01, tag);
  BOOST_TEST(f.max_record <= 0.01, tag);
  return f;
}

config::Config c3x() { return config::load_config_file(kExamples / "c3x_vane.json"); }

}  // namespace

BOOST_AUTO_TEST_CASE(rotor_split_step_without_names) { round_trip(config::builtin_example_config(), As::SplitStep, "rotor_split_step"); }

BOOST_AUTO_TEST_CASE(rotor_iges_faces) { round_trip(config::builtin_example_config(), As::Iges, "rotor_iges"); }

BOOST_AUTO_TEST_CASE(c3x_cascade_iges_faces) { round_trip(c3x(), As::Iges, "c3x_iges"); }

// A STEP file in metres (OCCT's reader scales it to the session's millimetres): the same blade.
BOOST_AUTO_TEST_CASE(c3x_step_in_metres) { round_trip(c3x(), As::MetreStep, "c3x_metre_step"); }

// The usual aero hand-over: the wall surface alone, reaching past hub and casing (no end faces).
BOOST_AUTO_TEST_CASE(c3x_wall_surface_past_hub_and_casing) { round_trip(c3x(), As::WallSurface, "c3x_wall_surface"); }

// The C3X vane (radial passages: a light cooled build) built by the CLI on its blade imported from the
// product's named STEP, from its geomTurbo export and from section tables of that (x y z, no sides: the
// default centre-line LE / TE, the convention of C3X's published profile): each valid, with the same
// feature names as the example's own build.
BOOST_AUTO_TEST_CASE(c3x_cooled_on_each_import_same_features) {
  test::TempDir dir("import_cad_cooled");
  const blade::BladeModel model = config::build_model(c3x());
  write_blade(model, As::NamedStep, dir.path / "blade.step");
  blade_import::write_geomturbo_file((dir.path / "blade.geomTurbo").string(), model);
  nlohmann::json original = c3x().source;
  original["output"]["formats"] = {"step"};
  for (auto& s : original.at("sections"))  // the copy lives in the temporary directory
    if (s.contains("points") && s["points"].contains("file"))
      s["points"]["file"] = (kExamples / s["points"]["file"].get<std::string>()).string();
  auto& passages = original["cooling"]["radial_passages"]["file"];
  passages = (kExamples / passages.get<std::string>()).lexically_normal().string();
  const char* formats[] = {"", "step", "geomturbo", "sections"};
  std::multiset<std::string> names[4];
  for (int k = 0; k < 4; ++k) {
    nlohmann::json cfg = original;
    if (k == 1) cfg = import_config(original, "step", dir.path / "blade.step");
    if (k == 2) {
      cfg = import_config(original, "geomturbo", dir.path / "blade.geomTurbo");
      cfg.erase("flow_path");
    }
    if (k == 3) {
      cfg.erase("sections");
      cfg["blade"]["import"] = test::tables_import(dir.path / "blade.geomTurbo", dir.path, cfg.at("flow_path"))["blade"]["import"];
    }
    const fs::path file = dir.path / ("config_" + std::to_string(k) + ".json"), out = dir.path / ("out" + std::to_string(k));
    std::ofstream(file) << cfg.dump();
    const test::Run run = test::run_cli("build " + test::q(file) + " -o " + test::q(out) + " -q", dir.path);
    BOOST_TEST_REQUIRE(run.exit_code == 0, formats[k] << ": " << run.err);
    const auto report = nlohmann::json::parse(test::read_text(out / "report.json"));
    // The part as OCCT's STEP reader gets it: valid solids, no free edges, the faces' feature names.
    const test::StepReadBack step = test::read_step_back(out / "blade.step");
    BOOST_TEST_REQUIRE(step.ok);
    for (const TopoDS_Shape& shape : step.free_shapes)
      for (TopExp_Explorer e(shape, TopAbs_SOLID); e.More(); e.Next()) {
        BOOST_TEST(BRepCheck_Analyzer(e.Current()).IsValid(), formats[k]);
        BOOST_TEST(test::free_edges(e.Current()) == 0, formats[k]);
      }
    names[k] = step.face_names;
    if (k == 0) continue;
    BOOST_TEST(report.at("model").at("import").at("format").get<std::string>() == formats[k]);
    const double max = report.at("model").at("import").at("deviation").at("max_mm").get<double>();
    BOOST_TEST_MESSAGE("C3X cooled on its " << formats[k] << " import: the import's maximum " << max << " mm");
    BOOST_TEST(max <= 0.01);
    if (k == 1) BOOST_TEST(report.at("model").at("import").at("sections").at(3).at("on_input_faces").at("points").get<int>() > 0);
    BOOST_TEST((names[0] == names[k]), formats[k] << ": feature names of the part on the imported blade equal the original's");
  }
  BOOST_TEST(names[0].count("radial_passage_1") == 1u);
}

// The file's bytes enter the input hash (a study's stage cache must not reuse a blade of an older file);
// the config reader does not cut the blade, so this costs no import.
BOOST_AUTO_TEST_CASE(step_file_bytes_enter_the_input_hash) {
  test::TempDir dir("import_cad_hash");
  write_blade(config::build_model(c3x()), As::NamedStep, dir.path / "blade.step");
  const nlohmann::json doc = import_config(c3x().source, "step", dir.path / "blade.step");
  const std::string before = pipeline::input_hash(config::parse_config(doc, kExamples, "hash"));
  std::ofstream(dir.path / "blade.step", std::ios::app) << "\n";
  BOOST_TEST(pipeline::input_hash(config::parse_config(doc, kExamples, "hash")) != before);
}

// ---- hostile files ---------------------------------------------------------------------------------

namespace {

// `coolinggen validate` of the C3X flow path with blade.import of `file`: exit 2, one line naming
// blade.import.file, the file and `words`.
void expect_refused(const fs::path& file, const char* format, const std::string& words) {
  test::TempDir dir("import_cad_hostile");
  nlohmann::json c = import_config(c3x().source, format, file);
  c.erase("cooling");
  std::ofstream(dir.path / "c.json") << c.dump();
  const test::Run r = test::run_cli("validate " + test::q(dir.path / "c.json"), dir.path);
  BOOST_TEST(r.exit_code == 2, file << ": exit " << r.exit_code << " " << r.err);
  BOOST_TEST(test::count_lines(r.err) == 1, r.err);
  BOOST_TEST(r.err.find("blade.import.file: ") != std::string::npos, r.err);
  BOOST_TEST(r.err.find(file.filename().string()) != std::string::npos, r.err);
  BOOST_TEST(r.err.find(words) != std::string::npos, r.err);
}

}  // namespace

BOOST_AUTO_TEST_CASE(not_a_step_file) {
  test::TempDir dir("import_cad_text");
  std::ofstream(dir.path / "blade.step") << "x y z\n1 2 3\n";
  expect_refused(dir.path / "blade.step", "step", "not a STEP file");
}

BOOST_AUTO_TEST_CASE(step_file_without_faces) {
  test::TempDir dir("import_cad_vertex");
  STEPControl_Writer w;
  BOOST_TEST_REQUIRE(w.Transfer(BRepBuilderAPI_MakeVertex(gp_Pnt(1, 2, 3)).Vertex(), STEPControl_AsIs) == IFSelect_RetDone);
  BOOST_TEST_REQUIRE(w.Write((dir.path / "vertex.step").c_str()) == IFSelect_RetDone);
  expect_refused(dir.path / "vertex.step", "step", "no face");
}

BOOST_AUTO_TEST_CASE(blade_short_of_the_casing) {
  test::TempDir dir("import_cad_short");
  const blade::BladeModel m = config::build_model(c3x());
  brep::PlaneTrim hub, tip;
  hub.point = Eigen::Vector3d(0, 0, m.trim.hub_z);
  tip.point = Eigen::Vector3d(0, 0, m.trim.hub_z + 0.8 * (m.trim.casing_z - m.trim.hub_z));
  const brep::BladeSolid short_blade = brep::build_blade_solid(m.surface, hub, tip);
  io::write_step(dir.path / "short.step", short_blade.solid, short_blade.faces);
  expect_refused(dir.path / "short.step", "step", "does not reach the casing");
}

namespace {

void write_plain_step(const TopoDS_Shape& shape, const fs::path& file) {
  STEPControl_Writer w;
  BOOST_TEST_REQUIRE(w.Transfer(shape, STEPControl_AsIs) == IFSelect_RetDone);
  BOOST_TEST_REQUIRE(w.Write(file.c_str()) == IFSelect_RetDone);
}

}  // namespace

BOOST_AUTO_TEST_CASE(two_blades_in_one_file) {
  test::TempDir dir("import_cad_two");
  const TopoDS_Solid blade = brep::build_blade_solid(config::build_model(c3x())).solid;
  gp_Trsf shift;
  shift.SetTranslation(gp_Vec(0, 150, 0));
  TopoDS_Compound both;
  BRep_Builder b;
  b.MakeCompound(both);
  b.Add(both, blade);
  b.Add(both, BRepBuilderAPI_Transform(blade, shift, Standard_True).Shape());
  write_plain_step(both, dir.path / "two.step");
  expect_refused(dir.path / "two.step", "step", "is not one closed outline (2 loops)");
}

BOOST_AUTO_TEST_CASE(wall_with_a_face_missing) {
  test::TempDir dir("import_cad_hole");
  const TopoDS_Solid blade = brep::build_blade_solid(config::build_model(c3x())).solid;
  GProp_GProps props;
  BRepGProp::SurfaceProperties(blade, props);
  ShapeUpgrade_ShapeDivideArea split(blade);
  split.MaxArea() = props.Mass() / 12;
  BOOST_TEST_REQUIRE(split.Perform());
  // Every face but the largest wall piece (the hub and casing faces are smaller than it).
  TopoDS_Face largest;
  double most = 0;
  for (TopExp_Explorer e(split.Result(), TopAbs_FACE); e.More(); e.Next()) {
    GProp_GProps f;
    BRepGProp::SurfaceProperties(e.Current(), f);
    if (f.Mass() > most) most = f.Mass(), largest = TopoDS::Face(e.Current());
  }
  TopoDS_Compound rest;
  BRep_Builder b;
  b.MakeCompound(rest);
  for (TopExp_Explorer e(split.Result(), TopAbs_FACE); e.More(); e.Next())
    if (!e.Current().IsSame(largest)) b.Add(rest, e.Current());
  write_plain_step(rest, dir.path / "hole.step");
  expect_refused(dir.path / "hole.step", "step", "ends open at");
}
