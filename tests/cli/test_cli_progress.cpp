// Issue 8 item 8, a user can see what happens: stage progress on a terminal (nothing when stdout is
// not a terminal or with -q), --timeout that stops cleanly naming the stage (and a watchdog that bounds
// the stop when a step has no check point), and report.json with the tool version, an input hash and
// per-section diagnostics.
#define BOOST_TEST_MODULE cli_progress
#include <boost/test/unit_test.hpp>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <thread>

#include "cli/run_cli.hpp"
#include "src/cli/console_progress.hpp"
#include "src/cli/suggest.hpp"
#include "src/cli/watchdog.hpp"
#include "export/version.hpp"

namespace fs = std::filesystem;
using namespace cg;
using nlohmann::json;
using test::q;
using test::read_text;
using test::TempDir;

namespace {

const fs::path kC3x = COOLINGGEN_SOURCE_DIR "/data/examples/c3x_vane.json";

// The C3X vane example writing blade.step only (its default formats and network add ~10 s a build and
// are tested elsewhere): a copy in `dir` with its point files' paths made absolute. Returns the copy.
fs::path c3x_step_only(const fs::path& dir) {
  json d = json::parse(read_text(kC3x));
  for (json* f : {&d["sections"][0]["points"]["file"], &d["cooling"]["radial_passages"]["file"]})
    *f = (kC3x.parent_path() / f->get<std::string>()).lexically_normal().string();
  d["output"] = {{"formats", {"step"}}};
  const fs::path file = dir / "c3x_step.json";
  std::ofstream(file) << d.dump(1);
  return file;
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

}  // namespace

// On a terminal each stage shows a line that is redrawn in place and ends with its time; not on a
// terminal, or with -q, no progress is printed.
BOOST_AUTO_TEST_CASE(progress_only_on_a_terminal) {
  TempDir dir("cli_tty");
  const fs::path c3x = c3x_step_only(dir.path);
  const test::Run tty = test::run_cli("build " + q(c3x) + " -o " + q(dir.path / "a"), dir.path, /*terminal=*/true);
  BOOST_TEST_REQUIRE(tty.exit_code == 0, tty.err);
  for (const char* stage : {"\r  blade model  ", "\r  solid (blade surface trimmed to the flow path)  ",
                            "\r  checks (BRepCheck, free edges, closed mesh, volume)  ", "\r  write blade.step  ",
                            "\r  write report.json  "})
    BOOST_TEST(contains(tty.out, stage), "no progress line '" << stage << "' in: " << tty.out);
  BOOST_TEST(contains(tty.out, "volume "));  // the summary follows
  const test::Run quiet = test::run_cli("build " + q(c3x) + " -q -o " + q(dir.path / "b"), dir.path, true);
  BOOST_TEST(quiet.exit_code == 0, quiet.err);
  BOOST_TEST(quiet.out.empty(), quiet.out);
  const test::Run pipe = test::run_cli("build " + q(c3x) + " -o " + q(dir.path / "c"), dir.path);
  BOOST_TEST(pipe.exit_code == 0, pipe.err);
  BOOST_TEST(!contains(pipe.out, "\r"));
  BOOST_TEST(!contains(pipe.out, "blade model"));
  BOOST_TEST(contains(pipe.out, "volume "));
}

// --timeout stops at the next check point: exit 6, one line naming the stage, and the output directory
// of an earlier run left as it was.
BOOST_AUTO_TEST_CASE(timeout_stops_cleanly) {
  TempDir dir("cli_timeout");
  const fs::path out = dir.path / "out", c3x = c3x_step_only(dir.path);
  BOOST_TEST_REQUIRE(test::run_cli("build " + q(c3x) + " -q -o " + q(out), dir.path).exit_code == 0);
  const std::string report = read_text(out / "report.json"), step = read_text(out / "blade.step");
  const test::Run r = test::run_cli("build " + q(c3x) + " --timeout 0.001 -o " + q(out), dir.path);
  BOOST_TEST(r.exit_code == 6, r.err);
  BOOST_TEST(test::count_lines(r.err) == 1, r.err);
  BOOST_TEST(r.err.rfind("coolinggen: error: time limit of 0.001 s reached: stopped ", 0) == 0u, r.err);
  BOOST_TEST(contains(r.err, "stage '"), r.err);
  BOOST_TEST(contains(r.err, "nothing written, " + out.string() + " left as it was"), r.err);
  BOOST_TEST(read_text(out / "report.json") == report);
  BOOST_TEST(read_text(out / "blade.step") == step);
  const test::Run bad = test::run_cli("build " + q(c3x) + " --timeout -1 -o " + q(out), dir.path);
  BOOST_TEST(bad.exit_code == 1, bad.err);
}

// Ctrl-C (SIGINT) stops the same way: exit 6, the reason, nothing written.
BOOST_AUTO_TEST_CASE(interrupt_stops_cleanly) {
  TempDir dir("cli_sigint");
  const fs::path out = dir.path / "out";
  const std::string cmd = "'" + test::kCliBinary.string() + "' build -q -o " + q(out) + " 2> " + q(dir.path / "err.txt") +
                          " & pid=$!; "
                          // Wait until the handler is installed (SIGINT, bit 1 of SigCgt), as a background
                          // job of a script ignores SIGINT until then; and until the job is coolinggen: the
                          // forked shell catches SIGINT itself until it execs (a kill then was a flaky failure).
                          "while [ -e /proc/$pid ] && ! { [ \"$(cat /proc/$pid/comm 2>/dev/null)\" = coolinggen ] && "
                          "awk '/^SigCgt/ {exit !index(\"2367abef\", substr($2, 16, 1))}' /proc/$pid/status; }; "
                          "do sleep 0.01; done; kill -INT $pid; wait $pid";
  const int status = std::system(cmd.c_str());  // sh -c
  const std::string err = read_text(dir.path / "err.txt");
  BOOST_TEST(WEXITSTATUS(status) == 6, err);
  BOOST_TEST(err.rfind("coolinggen: error: interrupted (Ctrl-C): stopped ", 0) == 0u, err);
  BOOST_TEST(!fs::exists(out));
}

// The stop is bounded whatever the build's speed: within the limit, the grace and process overhead.
// Either the build finished first (exit 0, under the limit) or it stopped naming a stage (exit 6) and
// wrote nothing.
BOOST_AUTO_TEST_CASE(timeout_is_bounded) {
  TempDir dir("cli_timeout_bound");
  const double limit = 1.5;
  const test::Run r = test::run_cli("build -q --timeout 1.5 -o " + q(dir.path / "out"), dir.path);
  BOOST_TEST((r.exit_code == 0 || r.exit_code == 6), r.err);
  // + 6 s for process start, teardown and a loaded CI machine (seen: 5 s of overhead at load 10 on 2 cores).
  BOOST_TEST(r.seconds < limit + cli::watchdog_grace(limit) + 6.0, r.seconds << " s: " << r.err);
  if (r.exit_code == 6) {
    BOOST_TEST(contains(r.err, "time limit of 1.5 s reached: stopped "), r.err);
    BOOST_TEST(contains(r.err, "stage '"), r.err);
    // Stopped before writing: no directory; while writing the outputs (several formats take seconds):
    // the directory was made and this run's files removed again.
    BOOST_TEST((!fs::exists(dir.path / "out") || fs::is_empty(dir.path / "out")), r.err);
  } else {
    BOOST_TEST(r.seconds < limit + 2.0);
  }
}

// The watchdog ends a job that does not reach a check point within the grace after the limit (run in a
// child process: it calls _Exit), and leaves alone a job that ends in time.
BOOST_AUTO_TEST_CASE(watchdog_ends_a_job_without_check_points) {
  TempDir dir("cli_watchdog");
  const fs::path err = dir.path / "stderr.txt";
  const auto t0 = std::chrono::steady_clock::now();
  const pid_t child = fork();
  BOOST_TEST_REQUIRE(child >= 0);
  if (child == 0) {
    if (!std::freopen(err.c_str(), "w", stderr)) std::_Exit(99);
    cli::ConsoleProgress console(false);
    pipeline::TimeLimit limit(&console, 0.05);
    cli::Watchdog watchdog(limit, console, 0.2, "out");
    console.stage_started("verify", "checks");
    console.stage_progress(0.5, "volume and area");
    std::this_thread::sleep_for(std::chrono::seconds(10));  // a step without check points
    std::_Exit(0);
  }
  int status = 0;
  waitpid(child, &status, 0);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  BOOST_TEST(WIFEXITED(status));
  BOOST_TEST(WEXITSTATUS(status) == 6);
  BOOST_TEST(seconds < 3.0, seconds);
  BOOST_TEST(read_text(err) == "coolinggen: error: time limit of 0.05 s reached: stopped in stage 'verify', at volume and "
                               "area (no check point came within 0.2 s of the limit); nothing written, out left as it was\n");
  {
    cli::ConsoleProgress console(false);
    pipeline::TimeLimit limit(&console, 0.05);
    {
      cli::Watchdog watchdog(limit, console, 0.2, "out");
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }  // ended in time: no exit
    BOOST_TEST(console.activity().empty());
  }
  BOOST_TEST(cli::watchdog_grace(1) == 2.0);
  BOOST_TEST(cli::watchdog_grace(100) == 10.0);
  BOOST_TEST(cli::watchdog_grace(1e4) == 30.0);
}

// report.json: the tool version (as --version), an input hash that follows the content, and per
// section the built chord, the section-frame stagger (the configured one), area and pole counts.
BOOST_AUTO_TEST_CASE(report_says_what_was_built_from_what) {
  TempDir dir("cli_report");
  const test::Run v = test::run_cli("--version", dir.path);
  BOOST_TEST(v.out == std::string("coolinggen ") + io::tool_version() + "\n");
  // The built-in example's sections on a straight flow path (quick to build).
  json cfg = json::parse(test::run_cli("example", dir.path).out);
  cfg["flow_path"] = {{"type", "straight"}, {"span", 50}};
  for (const char* k : {"showerhead", "film_rows"}) cfg["cooling"].erase(k);  // the film holes would triple its time
  cfg.erase("coolant");  // its per-row sinks name the film rows removed above
  cfg["output"]["formats"] = json::array();  // report.json alone: what this test reads
  std::ofstream(dir.path / "a.json") << cfg.dump(2);
  std::ofstream(dir.path / "b.json") << cfg.dump();  // same content, other formatting
  cfg["blade"]["overbuild"] = 0.06;
  cfg["booleans"] = {{"allow_perturbation", false}};
  std::ofstream(dir.path / "d.json") << cfg.dump();
  cfg["blade"]["overbuild"] = 0.05;
  cfg.erase("booleans");
  std::string hash[3];
  int i = 0;
  for (const char* name : {"a", "b", "d"}) {
    // b (a's content) takes a's cooling stage from the stage cache: the hash is of the inputs alone.
    const test::Run r = test::run_cli("build " + q(dir.path / (std::string(name) + ".json")) + " -q -o " + q(dir.path / name) +
                                          " --stage-cache " + q(dir.path / "cache"),
                                      dir.path);
    BOOST_TEST_REQUIRE(r.exit_code == 0, r.err);
    hash[i++] = json::parse(read_text(dir.path / name / "report.json")).at("input_hash").get<std::string>();
  }
  const json report = json::parse(read_text(dir.path / "a" / "report.json"));
  BOOST_TEST(report.at("version").get<std::string>() == io::tool_version());
  BOOST_TEST(hash[0].size() == 7u + 64u);
  BOOST_TEST(hash[0].find_first_not_of("0123456789abcdef", 7) == std::string::npos, hash[0]);
  BOOST_TEST(hash[1] == hash[0]);
  BOOST_TEST(hash[2] != hash[0]);

  const json& sections = report.at("model").at("sections");
  BOOST_TEST_REQUIRE(sections.size() == cfg.at("sections").size());
  for (std::size_t i = 0; i < sections.size(); ++i) {
    const json& s = sections[i];
    const json& p = cfg.at("sections")[i].at("parametric");
    BOOST_TEST(s.at("chord_mm").get<double>() > 0);
    BOOST_TEST(std::abs(s.at("profile").at("stagger_deg").get<double>() - p.at("stagger_deg").get<double>()) < 1e-9);
    BOOST_TEST(s.at("profile").at("area_mm2").get<double>() > 0);
    BOOST_TEST(s.at("profile").at("poles").get<int>() > 0);
    BOOST_TEST(s.at("poles_3d").get<int>() > 0);
  }
  BOOST_TEST(report.at("model").at("blade_surface").at("poles_u").get<int>() > 0);

  // Perturbed retries are listed (none may move the geometry when allow_perturbation is false).
  const json d = json::parse(read_text(dir.path / "d" / "report.json"));
  BOOST_TEST(report.at("booleans").at("allow_perturbation").get<bool>());
  BOOST_TEST(!d.at("booleans").at("allow_perturbation").get<bool>());
  for (const json* r : {&report, &d})
    for (const json& t : r->at("booleans").at("perturbed_tools")) {
      BOOST_TEST(!t.at("feature").get<std::string>().empty());
      BOOST_TEST(!t.at("change").get<std::string>().empty());
      if (r == &d) BOOST_TEST(!t.at("geometry_changed").get<bool>(), t.dump());
    }
}

BOOST_AUTO_TEST_CASE(suggestions) {
  BOOST_TEST(cli::edit_distance("biuld", "build") == 2);
  BOOST_TEST(cli::edit_distance("", "abc") == 3);
  BOOST_TEST(cli::closest_name("biuld", {"build", "validate", "example"}) == "build");
  BOOST_TEST(cli::closest_name("exampel", {"build", "validate", "example"}) == "example");
  BOOST_TEST(cli::closest_name("mesh", {"build", "validate", "example"}).empty());
}
