// The build as a library call (src/pipeline): stages in order with progress, cancellation that names
// the stage (also from inside OCCT's general fuse), outputs that never mix runs, report.json content
// (version, input hash, built chord) and the SHA-256 used for the input hash.
#define BOOST_TEST_MODULE pipeline
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <nlohmann/json.hpp>
#include <set>

#include "brep/temp_files.hpp"
#include "export/atomic_file.hpp"
#include "src/config/config.hpp"
#include "src/pipeline/build.hpp"
#include "src/pipeline/output_directory.hpp"
#include "src/pipeline/outputs.hpp"
#include "src/pipeline/report.hpp"
#include "src/pipeline/sha256.hpp"
#include "src/pipeline/time_limit.hpp"
#include "export/version.hpp"

namespace fs = std::filesystem;
using namespace cg;
using nlohmann::json;
using test::read_text;
using test::TempDir;

namespace {

const fs::path kC3x = COOLINGGEN_SOURCE_DIR "/data/examples/c3x_vane.json";

// The C3X example without its cooling (these tests are about the pipeline's stages on a plain blade;
// tests/features/test_passages_c3x.cpp runs the cooling stage).
config::Config c3x_uncooled() {
  config::Config c = config::load_config_file(kC3x);
  c.cooling = {};
  // ... and without the coolant network of its passages (a default format of the example).
  c.coolant.reset();
  c.output.formats.erase(std::remove(c.output.formats.begin(), c.output.formats.end(), config::OutputFormat::Network),
                         c.output.formats.end());
  return c;
}

// Records what the pipeline reports; asks to stop when `stop_in` starts (or, with stop_on_progress, at
// its first progress report).
struct RecordingSink : ProgressSink {
  std::mutex m;
  std::vector<std::string> started, finished;
  std::vector<std::pair<double, std::string>> progress;
  std::string current, stop_in;
  bool stop_on_progress = false;
  bool stop = false;
  void stage_started(const std::string& stage, const std::string&) override {
    std::lock_guard<std::mutex> l(m);
    started.push_back(stage);
    current = stage;
    if (stage == stop_in && !stop_on_progress) stop = true;
  }
  void stage_progress(double f, const std::string& step) override {
    std::lock_guard<std::mutex> l(m);
    progress.emplace_back(f, current + "/" + step);
    if (current == stop_in && stop_on_progress) stop = true;
  }
  void stage_finished(const std::string& stage, double) override {
    std::lock_guard<std::mutex> l(m);
    finished.push_back(stage);
  }
  bool stop_requested() const override { return stop; }
};

}  // namespace

BOOST_AUTO_TEST_CASE(build_as_library_call) {
  config::Config c = c3x_uncooled();
  c.output.formats = {config::OutputFormat::Step};  // the model file alone: the hand-off formats have their own tests (label export)
  RecordingSink sink;
  const pipeline::BuildResult r = pipeline::run_build(c, {}, &sink);
  BOOST_TEST(r.valid(), r.failed_checks());
  BOOST_TEST(r.failed_checks().empty());
  BOOST_TEST((sink.started == std::vector<std::string>{"blade_model", "solid", "verify"}));
  BOOST_TEST(sink.finished == sink.started);
  BOOST_TEST_REQUIRE(r.timings.size() == 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    BOOST_TEST(r.timings[i].stage == sink.started[i]);
    BOOST_TEST(r.timings[i].seconds >= 0);
  }
  // Progress from inside the stages: the solid (trimmed along the wall's iso-curves, src/brep/
  // blade_solid.hpp) and the checks (the mesh through the OCCT indicator).
  bool fuse = false, mesh = false;
  for (const auto& [f, step] : sink.progress) {
    BOOST_TEST((f >= 0 && f <= 1), step << " " << f);
    fuse = fuse || step == "solid/trimming along the wall's iso-curves";
    mesh = mesh || step.rfind("verify/closed_mesh", 0) == 0;
  }
  BOOST_TEST(fuse);
  BOOST_TEST(mesh);
  // The Part: one named body, every face named.
  BOOST_TEST_REQUIRE(r.part.size() == 1u);
  BOOST_TEST(r.part[0].name == "blade");
  BOOST_TEST(r.part[0].geometry.faces.size() == 3u);
  const auto names = brep::count_face_names(r.part[0].geometry);
  BOOST_TEST(names.at("blade_wall") == 1);
  BOOST_TEST(names.at("hub") == 1);
  BOOST_TEST(names.at("casing") == 1);
  BOOST_TEST(r.checks.size() == 1u);

  TempDir dir("pipeline_outputs");
  const pipeline::WrittenOutputs w = pipeline::write_outputs(c, r, dir.path / "out", &sink);
  BOOST_TEST((w.files == std::vector<std::string>{"blade.step", "report.json"}));
  auto entries = TempDir::entries_of(dir.path / "out");
  std::sort(entries.begin(), entries.end());
  BOOST_TEST((entries == std::vector<std::string>{"blade.step", "report.json"}));
  const json report = json::parse(read_text(dir.path / "out" / "report.json"));
  BOOST_TEST(report.at("version").get<std::string>() == io::tool_version());
  BOOST_TEST(report.at("input_hash").get<std::string>() == pipeline::input_hash(c));
  BOOST_TEST((report.at("outputs") == json{"blade.step", "report.json"}));
  for (const char* stage : {"blade_model", "solid", "verify", "step"}) BOOST_TEST(report.at("timings_s").contains(stage), stage);
  BOOST_TEST(report.at("model").at("source").get<std::string>() == kC3x.string());
}

// The README's design-study loop (two variants of the C3X vane): each variant's directory holds its
// own model, and the report's span follows the variant.
BOOST_AUTO_TEST_CASE(design_study_loop) {
  TempDir dir("pipeline_study");
  config::Config c = c3x_uncooled();
  for (int k = 0; k < 2; ++k) {
    std::get<blade::StraightFlowPath>(c.blade.flow_path).span = 100 + 20 * k;
    pipeline::TimeLimit limit(nullptr, 60);
    const pipeline::BuildResult r = pipeline::run_build(c, {}, &limit);
    BOOST_TEST(r.valid(), r.failed_checks());
    pipeline::write_outputs(c, r, dir.path / ("span" + std::to_string(k)));
  }
  for (int k = 0; k < 2; ++k) {
    const json report = json::parse(read_text(dir.path / ("span" + std::to_string(k)) / "report.json"));
    BOOST_TEST(report.at("model").at("span_length_mm").get<double>() == 100.0 + 20 * k);
    BOOST_TEST(fs::exists(dir.path / ("span" + std::to_string(k)) / "blade.step"));
  }
}

// A stop request ends the build with Cancelled naming the stage, before it starts or from inside OCCT.
BOOST_AUTO_TEST_CASE(cancel_names_the_stage) {
  const config::Config c = c3x_uncooled();
  for (const char* stage : {"blade_model", "verify"}) {
    RecordingSink sink;
    sink.stop_in = stage;
    try {
      pipeline::run_build(c, {}, &sink);
      BOOST_FAIL("no Cancelled for " << stage);
    } catch (const Cancelled& e) {
      BOOST_TEST(std::string(e.what()).find(std::string("stage '") + stage + "'") != std::string::npos, e.what());
    }
  }
  // Inside the solid stage (trimmed along the wall's iso-curves): its check point stops it, and nothing
  // after it runs.
  RecordingSink sink;
  sink.stop_in = "solid";
  sink.stop_on_progress = true;
  try {
    pipeline::run_build(c, {}, &sink);
    BOOST_FAIL("no Cancelled inside the solid stage");
  } catch (const Cancelled& e) {
    BOOST_TEST(e.what() == std::string("stopped in stage 'solid', at trimming along the wall's iso-curves"));
  }
  BOOST_TEST((sink.finished == std::vector<std::string>{"blade_model"}));
  // A stop requested after a stage's last check point is noticed before the next stage starts.
  struct StopAfter : RecordingSink {
    void stage_finished(const std::string& stage, double s) override {
      RecordingSink::stage_finished(stage, s);
      if (stage == "solid") stop = true;
    }
  } after;
  BOOST_CHECK_EXCEPTION(pipeline::run_build(c, {}, &after), Cancelled,
                        [](const Cancelled& e) { return e.what() == std::string("stopped before stage 'verify'"); });

  // A time limit: TimeLimit stops, and says why.
  pipeline::TimeLimit limit(nullptr, 1e-9);
  BOOST_CHECK_THROW(pipeline::run_build(c, {}, &limit), Cancelled);
  BOOST_TEST(limit.stop_reason().find("time limit of 1e-09 s") != std::string::npos, limit.stop_reason());
}

// The output directory holds one run's files only: a failed run removes the previous run's model
// files; a run that fails while writing leaves no outputs at all.
BOOST_AUTO_TEST_CASE(output_directory_never_mixes_runs) {
  TempDir dir("pipeline_outdir");
  const fs::path out = dir.path / "out";
  fs::create_directories(out);
  std::ofstream(out / "notes.txt") << "user file";
  std::ofstream(out / "blade.step") << "stale";
  std::ofstream(out / "old_extra.vtu") << "stale";
  std::ofstream(out / "report.json") << json{{"generator", "coolinggen"}, {"outputs", {"blade.step", "old_extra.vtu", "../escape", "report.json"}}}.dump();
  std::ofstream(dir.path / "escape") << "outside";
  {
    pipeline::OutputDirectory od(out, "report.json", {"blade.step"});
    auto e = TempDir::entries_of(out);
    BOOST_TEST((e == std::vector<std::string>{"notes.txt"}));  // stale outputs gone, the user's file kept
    od.write("a.txt", [](const fs::path& p) { std::ofstream(p) << "a"; });
    BOOST_CHECK_THROW(od.write("b.txt", [](const fs::path&) { throw io::ExportError("disk full"); }), io::ExportError);
    BOOST_CHECK_THROW(od.write("../c.txt", [](const fs::path& p) { std::ofstream(p) << "c"; }), io::ExportError);
  }  // not committed: a.txt removed again
  auto e = TempDir::entries_of(out);
  BOOST_TEST((e == std::vector<std::string>{"notes.txt"}));
  BOOST_TEST(fs::exists(dir.path / "escape"));  // names with a directory part are never removed

  {
    pipeline::OutputDirectory od(out, "report.json", {});
    od.write("a.txt", [](const fs::path& p) { std::ofstream(p) << "a"; });
    od.commit([](const fs::path& p, const std::vector<std::string>& files) {
      std::ofstream(p) << json{{"generator", "coolinggen"}, {"outputs", files}}.dump();
    });
  }
  e = TempDir::entries_of(out);
  std::sort(e.begin(), e.end());
  BOOST_TEST((e == std::vector<std::string>{"a.txt", "notes.txt", "report.json"}));
  BOOST_TEST((json::parse(read_text(out / "report.json")).at("outputs") == json{"a.txt", "report.json"}));
  // The next run removes a.txt through the index.
  { pipeline::OutputDirectory od(out, "report.json", {}); }
  e = TempDir::entries_of(out);
  BOOST_TEST((e == std::vector<std::string>{"notes.txt"}));
}

// A failed check writes report.json only (valid: false): no model, no blade.glb, no report.html, and
// removes those of an earlier run.
BOOST_AUTO_TEST_CASE(failed_checks_write_the_report_only) {
  const config::Config c = c3x_uncooled();
  pipeline::BuildResult r = pipeline::run_build(c);
  TempDir dir("pipeline_failed");
  pipeline::write_outputs(c, r, dir.path);
  for (const char* f : {"blade.step", "blade.glb", "report.html"}) BOOST_TEST(fs::exists(dir.path / f), f);
  r.checks[0].closed_mesh.passed = false;
  BOOST_TEST(!r.valid());
  BOOST_TEST(r.failed_checks() == "blade: closed_mesh");
  const pipeline::WrittenOutputs w = pipeline::write_outputs(c, r, dir.path);
  BOOST_TEST((w.files == std::vector<std::string>{"report.json"}));
  BOOST_TEST((dir.entries() == std::vector<std::string>{"report.json"}));
  const json report = json::parse(read_text(dir.path / "report.json"));
  BOOST_TEST(!report.at("valid").get<bool>());
  BOOST_TEST((report.at("outputs") == json{"report.json"}));
}

// report.json's chord is the built one: on a cylindrical flow path whose LE and TE lines are 30 mm
// apart axially, a stagger-0 section of chord 50 is scaled to fit between them, so its LE and TE (same
// theta) are 30 mm apart. The profile entry keeps the section-frame chord (50).
BOOST_AUTO_TEST_CASE(report_chord_is_the_built_chord) {
  json doc = {{"units", "mm"},
              {"flow_path",
               {{"type", "meridional"},
                {"hub", {{-20, 300}, {60, 300}}},
                {"casing", {{-20, 340}, {60, 340}}},
                {"leading_edge", {{0, 300}, {0, 340}}},
                {"trailing_edge", {{30, 300}, {30, 340}}}}},
              {"sections",
               {{{"span", 0},
                 {"parametric",
                  {{"chord", 50},
                   {"stagger_deg", 0},
                   {"inlet_metal_angle_deg", 20},
                   {"outlet_metal_angle_deg", -20},
                   {"max_thickness", 8},
                   {"le_radius", 2},
                   {"te_radius", 0.5}}}}}}};
  const config::Config c = config::parse_config(doc, ".", "cylinder");
  const blade::BladeModel m = pipeline::validate(c).model;
  const auto model = pipeline::report_model(c, m);
  const auto& s = model.at("sections").at(0);
  BOOST_TEST(std::abs(s.at("chord_mm").get<double>() - 30.0) < 1e-6, s.at("chord_mm"));
  BOOST_TEST(std::abs(s.at("profile").at("chord_mm").get<double>() - 50.0) < 1e-9);
  BOOST_TEST(std::abs(s.at("profile").at("stagger_deg").get<double>()) < 1e-9);
}

// The input hash follows the content (config and point files), not the formatting.
BOOST_AUTO_TEST_CASE(input_hash_follows_content) {
  TempDir dir("pipeline_hash");
  fs::copy_file(COOLINGGEN_SOURCE_DIR "/data/c3x/profile_table3_cm.csv", dir.path / "p.csv");
  json doc = json::parse(read_text(kC3x));
  doc["sections"][0]["points"]["file"] = "p.csv";
  doc["cooling"]["radial_passages"]["file"] = COOLINGGEN_SOURCE_DIR "/data/c3x/cooling_holes_fig7_cm.csv";
  std::ofstream(dir.path / "a.json") << doc.dump(2);
  std::ofstream(dir.path / "b.json") << doc.dump();
  const std::string a = pipeline::input_hash(config::load_config_file(dir.path / "a.json"));
  BOOST_TEST(a.rfind("sha256:", 0) == 0u);
  BOOST_TEST(a.size() == 7u + 64u);
  BOOST_TEST(pipeline::input_hash(config::load_config_file(dir.path / "b.json")) == a);
  std::ofstream(dir.path / "p.csv", std::ios::app) << "\n# edited\n";
  BOOST_TEST(pipeline::input_hash(config::load_config_file(dir.path / "b.json")) != a);
  doc["blade"]["overbuild"] = 0.06;
  std::ofstream(dir.path / "b.json") << doc.dump();
  BOOST_TEST(pipeline::input_hash(config::load_config_file(dir.path / "b.json")) != a);
}

// FIPS 180-4 example digests, and a message crossing block boundaries fed in uneven pieces.
BOOST_AUTO_TEST_CASE(sha256_known_digests) {
  const auto digest = [](const std::string& s) {
    pipeline::Sha256 h;
    h.update(s);
    return h.hex_digest();
  };
  BOOST_TEST(digest("") == "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  BOOST_TEST(digest("abc") == "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  const std::string two_blocks = "abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq";
  BOOST_TEST(digest(two_blocks) == "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
  const std::string million(1000000, 'a');
  pipeline::Sha256 h;
  for (std::size_t i = 0; i < million.size(); i += 997) h.update(million.data() + i, std::min<std::size_t>(997, million.size() - i));
  BOOST_TEST(h.hex_digest() == "cdc76e5c9914fb9281a1c7e284d73e67f1809a48a497200e046d39ccc7112cd0");
}
