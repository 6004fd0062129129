// The coolinggen executable run as a process: the built-in example and a straight C3X vane give a
// valid STEP (read back: one valid solid, volume equal to the report's to 1e-6 relative, the
// integration accuracy) and report.json (the built-in example's passage table: every chamber at every
// span, holes as holes); bad configs exit non-zero with one line on stderr naming
// the field, and write nothing (not even the output directory); --threads and the affinity mask bound
// a job's threads.
#define BOOST_TEST_MODULE cli_process
#include <boost/test/unit_test.hpp>

#include <STEPControl_Reader.hxx>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "brep/temp_files.hpp"
#include "cli/run_cli.hpp"
#include "support/ccx_run.hpp"
#include "support/fanno_exact.hpp"
#include "src/blade/section.hpp"
#include "src/brep/verify.hpp"

namespace fs = std::filesystem;
using namespace cg;

namespace {

using test::read_text;
using test::TempDir;

test::Run run(const std::string& args, const fs::path& dir) { return test::run_cli(args, dir); }
int lines(const std::string& s) { return test::count_lines(s); }

// Reads DIR/blade.step and DIR/report.json and checks them against each other.
void check_outputs(const fs::path& dir, const std::string& expected_name) {
  BOOST_TEST_REQUIRE(fs::exists(dir / "blade.step"));
  BOOST_TEST_REQUIRE(fs::exists(dir / "report.json"));
  const auto report = nlohmann::json::parse(read_text(dir / "report.json"));
  BOOST_TEST(report.at("valid").get<bool>());
  BOOST_TEST(report.at("model").at("name").get<std::string>() == expected_name);
  for (const auto& [name, c] : report.at("checks").items()) BOOST_TEST(c.at("passed").get<bool>(), name);
  STEPControl_Reader reader;
  BOOST_TEST_REQUIRE(reader.ReadFile((dir / "blade.step").string().c_str()) == IFSelect_RetDone);
  reader.TransferRoots();
  const cg::brep::SolidCheck c = cg::brep::verify_solid(reader.OneShape());
  for (const cg::brep::Check* k : c.checks()) BOOST_TEST(k->passed, k->name << ": " << k->message);
  const double v = report.at("solid").at("volume_mm3").get<double>();
  BOOST_TEST(v > 0);
  BOOST_TEST(std::abs(c.volume - v) <= 1e-6 * v, c.volume << " vs " << v);
  BOOST_TEST(c.face_count == report.at("solid").at("face_count").get<int>());
  const std::string step = read_text(dir / "blade.step");
  for (const char* n : {"blade_wall", "hub", "casing"})
    BOOST_TEST(step.find(std::string("ADVANCED_FACE('") + n + "'") != std::string::npos, n);
}

// The coolant network of c3x_vane.json's ten radial passages (its "coolant": supply 2.1 bar / 340 K at
// the open hub, 2.0 bar at the open tip): ccx runs the network.inp CoolingGen wrote (its own run, read
// from its .dat), and each passage's flow is compared with the exact Fanno + Colebrook integration
// (tests/support/fanno_exact.hpp) of a smooth tube of the passage's diameter (NASA CR-168015 Fig. 7:
// 6.30 mm x 7, 3.10 mm x 2, 1.98 mm) over the span, gas properties as network.json states them.
// Tolerance 3e-4 relative: ccx's Fanno element agrees with this integration to 1e-5 on one pipe
// (test_network_deck), the .dat has 7 digits, and the deck's passages are 0.02 mm (1.4e-4) shorter
// than the span (end stations 0.01 mm inside the open ends: about +7e-5 of flow). The split between
// the passages (each one's share of the total) against the ratio of their exact flows (resistances) to
// the same tolerance; the 6.30 mm passages carry clearly more than the 1.98 mm one.
void check_radial_passage_network(const fs::path& out, const nlohmann::json& cfg) {
  const cg::test::DeckRead deck = cg::test::read_deck(read_text(out / "network.inp"));
  const cg::test::CcxRun run = cg::test::run_ccx(out / "network.inp");
  BOOST_TEST_REQUIRE(run.converged, run.log);
  const nlohmann::json net = nlohmann::json::parse(read_text(out / "network.json"));
  const cg::test::FannoGas gas{net.at("gas").at("gas_constant_j_kg_k").get<double>(), net.at("gas").at("cp_j_kg_k").get<double>(),
                               net.at("gas").at("viscosity_pa_s").get<double>()};
  const double pt = cfg.at("coolant").at("supply").at("total_pressure_pa").get<double>();
  const double tt = cfg.at("coolant").at("supply").at("total_temperature_k").get<double>();
  const double sink = cfg.at("coolant").at("sinks").at("static_pressure_pa").get<double>();
  const double span = cfg.at("flow_path").at("span").get<double>(), pi = 3.14159265358979323846;
  const std::vector<double> diameters{6.30, 6.30, 6.30, 6.30, 6.30, 6.30, 6.30, 3.10, 3.10, 1.98};
  std::vector<double> ccx(10, 0), exact(10, 0);
  for (const auto& [id, name] : deck.name)
    for (std::size_t k = 0; k < 10; ++k)
      if (name == "radial_passage_" + std::to_string(k + 1) + "_seg_00") ccx[k] = run.mass_flow.at(deck.elements.at(id)[1]) * 1e3;
  double sum_ccx = 0, sum_exact = 0, worst = 0, worst_split = 0;
  for (std::size_t k = 0; k < 10; ++k) {
    const double d = diameters[k];
    exact[k] = cg::test::fanno_mass_flow({0.25 * pi * d * d, d, span, 0.0}, gas, pt, tt, sink);
    BOOST_TEST(std::abs(ccx[k] - exact[k]) / exact[k] < 3e-4, "radial_passage_" << k + 1 << ": ccx " << ccx[k] << " kg/s, exact " << exact[k]);
    worst = std::max(worst, std::abs(ccx[k] - exact[k]) / exact[k]);
    sum_ccx += ccx[k];
    sum_exact += exact[k];
  }
  for (std::size_t k = 0; k < 10; ++k) {
    const double split = (ccx[k] / sum_ccx) / (exact[k] / sum_exact) - 1;
    BOOST_TEST(std::abs(split) < 3e-4, "radial_passage_" << k + 1 << " share " << ccx[k] / sum_ccx << ", exact " << exact[k] / sum_exact);
    worst_split = std::max(worst_split, std::abs(split));
  }
  BOOST_TEST(ccx[0] / ccx[9] > 10);
  // network_results.json reports each passage's flow once (the supply's segment into it).
  const nlohmann::json res = nlohmann::json::parse(read_text(out / "network_results.json"));
  for (const auto& c : res.at("chambers")) {
    const std::size_t k = std::stoul(c.at("name").get<std::string>().substr(15)) - 1;
    BOOST_TEST(std::abs(c.at("mass_flow_kg_s").get<double>() - ccx[k]) <= 1e-6 * ccx[k], c.at("name") << ": " << c.at("mass_flow_kg_s"));
  }
  BOOST_TEST_MESSAGE("c3x_vane passages vs exact Fanno + Colebrook: worst relative " << worst << ", split " << worst_split
                     << "; flows 6.30 / 3.10 / 1.98 mm: " << ccx[0] << " / " << ccx[7] << " / " << ccx[9] << " kg/s");
}

}  // namespace

// The built-in example's build (its files, report and passage table) is checked by
// tests/acceptance/test_acceptance_builtin.cpp on the one product build that test shares.

// data/examples/c3x_vane.json: a straight vane from the C3X points (file path relative to the config).
BOOST_AUTO_TEST_CASE(straight_c3x_vane_builds) {
  TempDir dir("cli_c3x");
  const std::string cfg = COOLINGGEN_SOURCE_DIR "/data/examples/c3x_vane.json";
  const test::Run v = run("validate '" + cfg + "'", dir.path);
  BOOST_TEST(v.exit_code == 0, v.err);
  const test::Run r = run("build '" + cfg + "' -q -o '" + (dir.path / "out").string() + "'", dir.path);
  BOOST_TEST_REQUIRE(r.exit_code == 0, r.err);
  BOOST_TEST(r.out.empty());
  check_outputs(dir.path / "out", "c3x_vane");
  // Prismatic vane: volume = (section area - passage areas) x span. The area of the interpolated C3X profile (Green's
  // theorem in our kernel) differs from the blade surface's section only by the surface's
  // re-interpolation at its chordwise samples: 1e-4 relative.
  const double span = nlohmann::json::parse(read_text(cfg)).at("flow_path").at("span").get<double>();
  const auto report = nlohmann::json::parse(read_text(dir.path / "out" / "report.json"));
  const double volume = report.at("solid").at("volume_mm3").get<double>();
  cg::blade::PointSectionDefinition def;
  def.points = cg::blade::read_section_points(COOLINGGEN_SOURCE_DIR "/data/c3x/profile_table3_cm.csv", cg::blade::LengthUnit::Centimetre);
  double area = std::abs(cg::blade::section_properties(cg::blade::section_from_points(def).curve).area);
  // Minus the ten radial passages (NASA CR-168015 Fig. 7: diameters 6.30 mm x 7, 3.10 mm x 2, 1.98 mm).
  const double pi = 3.14159265358979323846;
  area -= 0.25 * pi * (7 * 6.30 * 6.30 + 2 * 3.10 * 3.10 + 1.98 * 1.98);
  BOOST_TEST(std::abs(volume / span - area) < 1e-4 * area, volume / span << " vs " << area);
  BOOST_TEST(std::abs(report.at("solid").at("bbox_mm").at("size").at(2).get<double>() - span) < 1e-6);
  check_radial_passage_network(dir.path / "out", nlohmann::json::parse(read_text(cfg)));
}

// The AP242 schema option reaches the file; without -q the build prints its summary on stdout.
BOOST_AUTO_TEST_CASE(ap242_option) {
  TempDir dir("cli_ap242");
  nlohmann::json cfg = nlohmann::json::parse(read_text(COOLINGGEN_SOURCE_DIR "/data/examples/c3x_vane.json"));
  cfg["sections"][0]["points"]["file"] = COOLINGGEN_SOURCE_DIR "/data/c3x/profile_table3_cm.csv";
  cfg.erase("cooling");
  cfg["output"]["step_schema"] = "AP242";
  cfg["flow_path"]["span"] = 20.0;
  std::ofstream(dir.path / "c3x.json") << cfg.dump(2);
  const test::Run r = run("build '" + (dir.path / "c3x.json").string() + "' -o '" + (dir.path / "out").string() + "'", dir.path);
  BOOST_TEST_REQUIRE(r.exit_code == 0, r.err);
  BOOST_TEST(r.err.empty(), r.err);
  BOOST_TEST(r.out.find("volume") != std::string::npos, r.out);
  BOOST_TEST(read_text(dir.path / "out" / "blade.step").find("AP242") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(bad_config_fails_without_output) {
  TempDir dir("cli_bad");
  // Take the built-in example (printed by `coolinggen example`) and break one field.
  nlohmann::json cfg;
  {
    TempDir ex("cli_example_json");
    const test::Run e = run("example", ex.path);
    BOOST_TEST_REQUIRE(e.exit_code == 0);
    cfg = nlohmann::json::parse(e.out);
  }
  cfg["sections"][2]["parametric"]["max_thickness"] = -2.0;
  std::ofstream(dir.path / "bad.json") << cfg.dump(2);
  const fs::path out = dir.path / "out";
  const test::Run b = run("build '" + (dir.path / "bad.json").string() + "' -o '" + out.string() + "'", dir.path);
  BOOST_TEST(b.exit_code == 2);
  BOOST_TEST(lines(b.err) == 1, b.err);
  BOOST_TEST(b.err.find("sections[2].parametric.max_thickness") != std::string::npos, b.err);
  BOOST_TEST(b.out.empty());
  BOOST_TEST(!fs::exists(out));

  const test::Run v = run("validate '" + (dir.path / "bad.json").string() + "'", dir.path);
  BOOST_TEST(v.exit_code == 2);
  BOOST_TEST(lines(v.err) == 1, v.err);

  const test::Run missing = run("validate '" + (dir.path / "none.json").string() + "'", dir.path);
  BOOST_TEST(missing.exit_code != 0);
  BOOST_TEST(lines(missing.err) == 1, missing.err);

  const test::Run usage = run("build", dir.path);  // -o missing
  BOOST_TEST(usage.exit_code == 1);
  BOOST_TEST(lines(usage.err) == 1, usage.err);
  const test::Run nothing = run("", dir.path);
  BOOST_TEST(nothing.exit_code != 0);
}

BOOST_AUTO_TEST_CASE(help_lists_commands) {
  TempDir dir("cli_help");
  const test::Run h = run("--help", dir.path);
  BOOST_TEST(h.exit_code == 0);
  for (const char* cmd : {"build", "validate", "example"}) BOOST_TEST(h.out.find(cmd) != std::string::npos, cmd);
}

// The executable starts without the hand-off libraries (src/cli/output_jobs.hpp): readelf (binutils) lists
// what it needs; none of VTK, gmsh, CGNS or OCCT's data exchange and visualisation. A copy without its
// output module still validates, and its build fails at once as CoolingGen's failure (exit 3, one line
// naming the module), before the build and with the output directory untouched.
BOOST_AUTO_TEST_CASE(output_module_loaded_only_to_write) {
  TempDir dir("cli_module");
  BOOST_TEST_REQUIRE(std::system(("readelf -d " + test::q(test::kCliBinary) + " > " + test::q(dir.path / "needed.txt")).c_str()) == 0);
  const std::string needed = read_text(dir.path / "needed.txt");
  BOOST_TEST_REQUIRE(needed.find("libTKernel") != std::string::npos, needed);  // readelf listed the libraries
  for (const char* heavy : {"vtk", "gmsh", "cgns", "TKXDE", "TKXCAF", "TKRWMesh", "TKV3d", "TKService"})
    BOOST_TEST(needed.find(heavy) == std::string::npos, heavy << " in " << needed);

  const fs::path alone = dir.path / "bin" / "coolinggen";
  fs::create_directories(alone.parent_path());
  fs::copy_file(test::kCliBinary, alone);
  const fs::path cfg = dir.path / "example.json";
  BOOST_TEST_REQUIRE(std::system((test::q(alone) + " example > " + test::q(cfg)).c_str()) == 0);
  const auto status = [&](const std::string& args) {
    const int s = std::system((test::q(alone) + " " + args + " > /dev/null 2> " + test::q(dir.path / "err.txt")).c_str());
    return WIFEXITED(s) ? WEXITSTATUS(s) : -1;
  };
  BOOST_TEST(status("validate " + test::q(cfg)) == 0, read_text(dir.path / "err.txt"));
  const fs::path out = dir.path / "out";
  const auto t0 = std::chrono::steady_clock::now();
  BOOST_TEST(status("build " + test::q(cfg) + " -o " + test::q(out)) == 3);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const std::string err = read_text(dir.path / "err.txt");
  BOOST_TEST(lines(err) == 1, err);
  BOOST_TEST(err.find("CoolingGen failure") != std::string::npos, err);
  BOOST_TEST(err.find("libcoolinggen_outputs.so is missing") != std::string::npos, err);
  BOOST_TEST(seconds < 5.0, seconds << " s: the module is looked for before the build (a build takes > 10 s)");
  BOOST_TEST(!fs::exists(out));
}

// --threads and the affinity mask bound the threads a job computes on (src/cli/threads.hpp): a build of a
// plain vane with --threads 1 runs on one thread throughout (its threads counted in /proc while it runs)
// and says so in report.json; a validate of the built-in example under `taskset -c 0` (util-linux) runs
// on one thread where it would start a worker per CPU; a COOLINGGEN_THREADS that is not a whole number
// is a command-line error naming it, before anything is written.
BOOST_AUTO_TEST_CASE(threads_follow_the_option_and_the_affinity) {
  TempDir dir("cli_threads");
  nlohmann::json cfg = nlohmann::json::parse(read_text(COOLINGGEN_SOURCE_DIR "/data/examples/c3x_vane.json"));
  cfg["sections"][0]["points"]["file"] = COOLINGGEN_SOURCE_DIR "/data/c3x/profile_table3_cm.csv";
  cfg.erase("cooling");
  cfg["flow_path"]["span"] = 20.0;
  cfg["output"]["formats"] = {"step"};  // (the previews' renderer keeps idle helper threads of its own)
  std::ofstream(dir.path / "c3x.json") << cfg.dump(2);
  // The most threads `coolinggen ARGS` had at once (polled from /proc while it runs).
  const auto peak_threads = [&](const std::string& prefix, const std::string& args) {
    const std::string script = prefix + " " + test::q(test::kCliBinary) + " " + args + " > /dev/null 2>&1 & p=$!; m=0; " +
                               "while kill -0 $p 2> /dev/null; do n=$(ls /proc/$p/task 2> /dev/null | wc -l); " +
                               "[ \"$n\" -gt \"$m\" ] && m=$n; done; wait $p; echo \"$? $m\" > " + test::q(dir.path / "peak.txt");
    BOOST_TEST_REQUIRE(std::system(("bash -c " + test::q(script)).c_str()) == 0);
    std::istringstream in(read_text(dir.path / "peak.txt"));
    int code = -1, peak = 0;
    in >> code >> peak;
    BOOST_TEST(code == 0, args);
    return peak;
  };
  const fs::path out = dir.path / "out";
  BOOST_TEST(peak_threads("", "build " + test::q(dir.path / "c3x.json") + " -q -o " + test::q(out) + " --threads 1") == 1);
  BOOST_TEST(nlohmann::json::parse(read_text(out / "report.json")).at("threads").get<int>() == 1);
  const std::string example = "validate " + test::q(COOLINGGEN_SOURCE_DIR "/data/examples/hpt_rotor.json");
  BOOST_TEST(peak_threads("taskset -c 0", example) == 1);

  const int bad = std::system(("COOLINGGEN_THREADS=two " + test::q(test::kCliBinary) + " build " + test::q(dir.path / "c3x.json") +
                               " -o " + test::q(dir.path / "bad") + " 2> " + test::q(dir.path / "err.txt")).c_str());
  BOOST_TEST((WIFEXITED(bad) && WEXITSTATUS(bad) == 1));
  const std::string err = read_text(dir.path / "err.txt");
  BOOST_TEST(lines(err) == 1, err);
  BOOST_TEST(err.find("COOLINGGEN_THREADS must be a whole number in [1, 1024], got 'two'") != std::string::npos, err);
  BOOST_TEST(!fs::exists(dir.path / "bad"));
}
