// Issue 22: `coolinggen sweep` run as a process on a light study (two-pass core, one rib, ~3 s per
// build): variants built in parallel by coolinggen build processes, a refused variant without a
// process, results.csv against each variant's report.json, resume (nothing rebuilt; a changed row
// rebuilds only itself), a timeout, Ctrl-C, study-file errors naming the field, --emit slurm and
// --collect; study_report.html in a real browser; and the designs (grid, Latin hypercube) in process.
// Each variant computes on its share of the CPUs (report.json "threads").
#define BOOST_TEST_MODULE study_sweep
#include <boost/test/unit_test.hpp>
#include <sched.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <thread>

#include "acceptance/browser.hpp"
#include "cli/run_cli.hpp"
#include "study/results_csv.hpp"
#include "src/config/config_error.hpp"
#include "src/study/design.hpp"
#include "src/study/field_path.hpp"
#include "src/core/process_pool.hpp"

namespace fs = std::filesystem;
using namespace cg;
using nlohmann::json;
using test::q;
using test::read_results;
using test::read_text;
using test::TempDir;

namespace {

const fs::path kBase = COOLINGGEN_SOURCE_DIR "/tests/study/light_base.json";

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

void write(const fs::path& f, const std::string& text) { std::ofstream(f) << text; }

// The study: the base by path, the rib's suction-side position and the wall thickness set, every
// section's stagger offset; variants from a CSV file.
std::string study_text(const std::string& extra_parameter = "") {
  json s{{"name", "light"},
         {"base", kBase.string()},
         {"parameters",
          {{{"name", "rib_ss"}, {"path", "cooling.core.ribs[0].suction_chord"}, {"range", {0.4, 0.52}}},
           {{"name", "wall"}, {"path", "cooling.core.wall_thickness"}, {"range", {0.8, 1.2}}},
           {{"name", "stagger"}, {"path", "sections[*].parametric.stagger_deg"}, {"mode", "offset"}, {"range", {-1, 1}}}}},
         {"design", {{"type", "csv"}, {"file", "rows.csv"}}},
         {"outputs", {"html"}}};  // report.html per variant: study_report.html links to it
  if (!extra_parameter.empty()) s["parameters"].push_back(json::parse(extra_parameter));
  return s.dump(1);
}

long long mtime(const fs::path& f) { return fs::last_write_time(f).time_since_epoch().count(); }

// study_report.html of the three-variant study (2 built, 1 refused; variants write report.html) in
// headless Chromium (skipped outside CI when Chromium is missing): status counts, the refusal's field,
// one plot per parameter and metric with every variant in it (the refused one in the no-value band),
// points linking to the variants' report.html, which exist. Screenshot: <build>/tests/screenshots.
void check_study_page(const fs::path& out) {
  for (const char* id : {"000", "001"}) BOOST_TEST(fs::exists(out / "variants" / id / "report.html"), id);
  const std::string html = read_text(out / "study_report.html");
  BOOST_TEST(contains(html, "\"link\":\"variants/000/report.html\""));
  const std::string missing = test::missing_browser_tools();
  const char* ci = std::getenv("CI");
  if (!missing.empty() && !(ci && std::string(ci) == "true")) {
    BOOST_TEST_MESSAGE("study_report.html browser check skipped, missing:" << missing << " (under CI=true this fails)");
    return;
  }
  const std::string dom = test::chromium(out / "study_report.html", "");
  const auto v = test::element_attributes(dom, "cg-verdict");
  BOOST_TEST_REQUIRE(v.count("data-state") == 1u, dom.substr(0, 2000));
  BOOST_TEST(v.at("data-state") == "rendered");
  BOOST_TEST(v.at("data-variants") == "3");
  // Metrics with a value in a built variant: solid and coolant volume, min wall, min rib, holes, build time.
  const int plots = 3 * 6;
  BOOST_TEST(std::stoi(v.at("data-plots")) == plots);
  BOOST_TEST(std::stoi(v.at("data-points")) == plots * 3);
  BOOST_TEST(test::table_rows(dom, "status-table") == 2);
  BOOST_TEST(test::table_rows(dom, "refusal-table") == 1);
  BOOST_TEST(contains(dom, "<td>cooling.core.wall_thickness</td>"));
  BOOST_TEST(contains(dom, "href=\"variants/001/report.html\""));
  fs::create_directories(test::kScreenshots);
  test::chromium(out / "study_report.html", "", test::kScreenshots / "study_report.png");
  BOOST_TEST(fs::exists(test::kScreenshots / "study_report.png"));
}

}  // namespace

BOOST_AUTO_TEST_CASE(field_paths) {
  const study::FieldPath p = study::parse_field_path("sections[*].parametric.stagger_deg", "parameters[0].path");
  BOOST_TEST(p.steps.size() == 4u);
  json doc = json::parse(R"({"sections": [{"parametric": {"stagger_deg": -22}}, {"parametric": {"stagger_deg": -30}}]})");
  study::apply_field(doc, p, study::ApplyMode::kOffset, 1.5, "parameters[0].path");
  BOOST_TEST(doc["sections"][0]["parametric"]["stagger_deg"].get<double>() == -20.5);  // exact in binary
  BOOST_TEST(doc["sections"][1]["parametric"]["stagger_deg"].get<double>() == -28.5);
  const auto error = [&](const std::string& path, study::ApplyMode mode = study::ApplyMode::kSet) {
    try {
      json d = doc;
      study::apply_field(d, study::parse_field_path(path, "parameters[2].path"), mode, 1.0, "parameters[2].path");
    } catch (const config::ConfigError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  BOOST_TEST(error("sections[2].parametric.chord").rfind("parameters[2].path: 'sections[2].parametric.chord': sections has 2 elements in the base config, index 2 is not in [0, 1]", 0) == 0u,
             error("sections[2].parametric.chord"));
  BOOST_TEST(contains(error("sections[0].shape.chord"), "sections[0].shape is not in the base config"));
  BOOST_TEST(contains(error("sections[0].parametric.chord", study::ApplyMode::kOffset), "sections[0].parametric.chord is not in the base config"));
  BOOST_TEST(error("sections[0].parametric.chord").empty());  // set creates the member; config parsing judges it
  BOOST_TEST(contains(error("sections..x"), "is not a config field path"));
  BOOST_TEST(contains(error("sections[x].span"), "an index is a number or *"));
}

// Each parameter's samples fall in distinct strata; the same seed gives the same points; maximin over
// 20 draws spreads the points at least as well as the first draw alone.
BOOST_AUTO_TEST_CASE(latin_hypercube_design) {
  const auto a = study::latin_hypercube(24, 3, 7, 20), b = study::latin_hypercube(24, 3, 7, 20);
  BOOST_TEST(a == b);
  BOOST_TEST(a != study::latin_hypercube(24, 3, 8, 20));
  for (int k = 0; k < 3; ++k) {
    std::set<int> strata;
    for (const auto& p : a) strata.insert(static_cast<int>(std::floor(p[k] * 24)));
    BOOST_TEST(strata.size() == 24u);
  }
  const auto min_d = [](const std::vector<std::vector<double>>& pts) {
    double m = HUGE_VAL;
    for (std::size_t i = 0; i < pts.size(); ++i)
      for (std::size_t j = i + 1; j < pts.size(); ++j) {
        double d = 0;
        for (std::size_t k = 0; k < pts[i].size(); ++k) d += std::pow(pts[i][k] - pts[j][k], 2);
        m = std::min(m, d);
      }
    return m;
  };
  BOOST_TEST(min_d(a) >= min_d(study::latin_hypercube(24, 3, 7, 1)));
}

// Study-file errors: one line naming the study field, exit 2, nothing built.
BOOST_AUTO_TEST_CASE(study_errors) {
  TempDir dir("study_errors");
  write(dir.path / "rows.csv", "rib_ss,wall,stagger\n0.46,1.0,0\n");
  const auto run = [&](const std::string& text) {
    write(dir.path / "s.json", text);
    return test::run_cli("sweep " + q(dir.path / "s.json") + " -o " + q(dir.path / "out"), dir.path);
  };
  std::string s = study_text();
  s.replace(s.find("ribs[0]"), 7, "ribz[0]");
  test::Run r = run(s);
  BOOST_TEST(r.exit_code == 2, r.err);
  BOOST_TEST(test::count_lines(r.err) == 1, r.err);
  BOOST_TEST(r.err.rfind("coolinggen: error: parameters[0].path: 'cooling.core.ribz[0].suction_chord': cooling.core.ribz is not in the base config", 0) == 0u, r.err);
  s = study_text();
  s.replace(s.find("ribs[0]"), 7, "ribs[3]");
  r = run(s);
  BOOST_TEST(r.exit_code == 2, r.err);
  BOOST_TEST(contains(r.err, "parameters[0].path: 'cooling.core.ribs[3].suction_chord': cooling.core.ribs has 1 element in the base config, index 3 is not in [0, 0]"), r.err);
  r = run(study_text(R"({"path": "cooling.core.wall_thicknes", "values": [1]})"));  // a key the config does not know
  BOOST_TEST(r.exit_code == 2, r.err);
  BOOST_TEST(r.err.rfind("coolinggen: error: parameters[3].path: 'cooling.core.wall_thicknes': cooling.core.wall_thicknes: unknown key", 0) == 0u, r.err);
  r = run(study_text(R"({"path": "cooling.core.wall_thickness", "range": [2, 1]})"));
  BOOST_TEST(r.exit_code == 2, r.err);
  BOOST_TEST(contains(r.err, "parameters[3].range: must be [lo, hi] with lo < hi, got [2, 1]"), r.err);
  s = study_text();
  s.replace(s.find("\"csv\""), 5, "\"latin\"");
  r = run(s);
  BOOST_TEST(r.exit_code == 2, r.err);
  BOOST_TEST(contains(r.err, "design.type: must be one of"), r.err);
  s = study_text();
  s.replace(s.find("\"html\""), 6, "\"html\", \"gltf\"");
  r = run(s);
  BOOST_TEST(r.exit_code == 2, r.err);
  BOOST_TEST(contains(r.err, "outputs[1]: unknown output format \"gltf\" (allowed: \"step\", \"iges\""), r.err);
  write(dir.path / "rows.csv", "rib_ss,wall\n0.46,1.0\n");
  r = run(study_text());
  BOOST_TEST(r.exit_code == 2, r.err);
  BOOST_TEST(contains(r.err, "design.file: rows.csv: no column 'stagger' (parameters[2])"), r.err);
  BOOST_TEST(!fs::exists(dir.path / "out"));
}

// The whole cycle on three variants, two builds at a time.
BOOST_AUTO_TEST_CASE(sweep_builds_resumes_and_collects) {
  TempDir dir("study_sweep");
  const fs::path study = dir.path / "study.json", out = dir.path / "out";
  write(study, study_text());
  // 002: a 50 mm wall, refused by the config's range check before anything is built.
  write(dir.path / "rows.csv", "rib_ss,wall,stagger\n0.42,0.9,1.0\n0.5,1.1,-1\n0.46,50,0\n");

  // Ctrl-C while both builds run: exit 6, no variant finished, every row pending or refused, no child left.
  {
    const pid_t pid = fork();
    if (pid == 0) {
      freopen("/dev/null", "w", stderr);  // its one-line "interrupted" message is checked by the exit code
      execl(test::kCliBinary.c_str(), "coolinggen", "sweep", study.c_str(), "-o", out.c_str(), "--jobs", "2", "-q", nullptr);
      _exit(127);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(1500));  // validation ~0.5 s, each build ~3 s
    kill(pid, SIGINT);
    int status = 0;
    waitpid(pid, &status, 0);
    BOOST_TEST(WIFEXITED(status));
    BOOST_TEST(WEXITSTATUS(status) == 6);
    const auto rows = read_results(out / "results.csv");
    BOOST_TEST_REQUIRE(rows.size() == 3u);
    BOOST_TEST(rows[0].at("status") == "pending");
    BOOST_TEST(rows[1].at("status") == "pending");
    BOOST_TEST(rows[2].at("status") == "refused");
    BOOST_TEST(!fs::exists(out / "variants/000/report.json"));
    // ("[c]" keeps the pattern from matching the shell that runs pgrep.)
    BOOST_TEST(std::system(("pgrep -f '[c]oolinggen build " + (out / "variants").string() + "' > /dev/null").c_str()) != 0,
               "a variant's process outlived the sweep");
  }

  const test::Run first = test::run_cli("sweep " + q(study) + " -o " + q(out) + " --jobs 2", dir.path);
  BOOST_TEST_REQUIRE(first.exit_code == 0, first.err);
  BOOST_TEST(contains(first.out, "3 variants (2 built, 1 refused); 2 run now, 0 up to date"), first.out);
  auto rows = read_results(out / "results.csv");
  BOOST_TEST_REQUIRE(rows.size() == 3u);
  for (int i = 0; i < 2; ++i) {
    const auto& row = rows[i];
    const fs::path vdir = out / "variants" / row.at("id");
    BOOST_TEST(row.at("status") == "built");
    BOOST_TEST(row.at("exit_code") == "0");
    // The variant's config has the values applied.
    const json config = json::parse(read_text(vdir / "config.json"));
    const json base = json::parse(read_text(kBase));
    BOOST_TEST(config["cooling"]["core"]["ribs"][0]["suction_chord"].get<double>() == std::stod(row.at("rib_ss")));
    for (std::size_t s = 0; s < base["sections"].size(); ++s)
      BOOST_TEST(config["sections"][s]["parametric"]["stagger_deg"].get<double>() ==
                 base["sections"][s]["parametric"]["stagger_deg"].get<double>() + std::stod(row.at("stagger")));
    // The row's metrics are the report's.
    const json report = json::parse(read_text(vdir / "report.json"));
    BOOST_TEST(std::stod(row.at("solid_volume_mm3")) == report["solid"]["volume_mm3"].get<double>());
    double wall = HUGE_VAL;
    for (const json& t : report["model"]["cooling"]["thickness"])
      if (t["feature"] == "outer_wall") wall = t["min_mm"].get<double>();
    BOOST_TEST(std::stod(row.at("min_wall_mm")) == wall);
    // The measured wall is the configured one, within the report's own check tolerance (1 % of it).
    BOOST_TEST(std::abs(wall - std::stod(row.at("wall"))) <= 0.01 * std::stod(row.at("wall")));
    BOOST_TEST(std::stod(row.at("chamber_1_dh_min_mm")) > 0);
    BOOST_TEST(std::stod(row.at("chamber_1_dh_mean_mm")) >= std::stod(row.at("chamber_1_dh_min_mm")));
    BOOST_TEST(row.at("hole_count") == "0");
    BOOST_TEST(row.at("error").empty(), row.at("error"));  // a built variant has no error
    BOOST_TEST(std::stod(row.at("build_s")) > 0);
    // Two variants at a time share the CPUs: each computes on half of them (at least one thread).
    cpu_set_t mask;
    BOOST_TEST_REQUIRE(sched_getaffinity(0, sizeof mask, &mask) == 0);
    BOOST_TEST(report.at("threads").get<int>() == std::max(1, CPU_COUNT(&mask) / 2));
  }
  BOOST_TEST(rows[2].at("status") == "refused");
  BOOST_TEST(rows[2].at("error").rfind("cooling.core.wall_thickness: must be ", 0) == 0u, rows[2].at("error"));
  BOOST_TEST(!fs::exists(out / "variants/002/build.log"));  // no process
  const std::string report_md = read_text(out / "study_report.md");
  BOOST_TEST(contains(report_md, "| built | 2 |"), report_md);
  BOOST_TEST(contains(report_md, "| `cooling.core.wall_thickness` | 1 | 002 |"), report_md);
  check_study_page(out);

  // Resume: nothing rebuilt (on a terminal, with its progress line).
  const auto t0 = mtime(out / "variants/000/report.json"), t1 = mtime(out / "variants/001/report.json");
  const std::string csv = read_text(out / "results.csv");
  const test::Run again = test::run_cli("sweep " + q(study) + " -o " + q(out) + " --jobs 2", dir.path, /*terminal=*/true);
  BOOST_TEST(again.exit_code == 0, again.err);
  BOOST_TEST(contains(again.out, "0 run now, 2 up to date"), again.out);
  BOOST_TEST(contains(again.out, "\rsweep: 3/3 done (2 built, 0 failed, 1 refused), 0 remaining"), again.out);
  BOOST_TEST(!contains(first.out, "\r"), first.out);  // not a terminal: no progress line
  BOOST_TEST(mtime(out / "variants/000/report.json") == t0);
  BOOST_TEST(read_text(out / "results.csv") == csv);

  // A changed row rebuilds only its variant.
  write(dir.path / "rows.csv", "rib_ss,wall,stagger\n0.42,0.9,1.0\n0.5,1.0,-1\n0.46,50,0\n");
  const test::Run changed = test::run_cli("sweep " + q(study) + " -o " + q(out) + " --jobs 2", dir.path);
  BOOST_TEST(changed.exit_code == 0, changed.err);
  BOOST_TEST(contains(changed.out, "1 run now, 1 up to date"), changed.out);
  BOOST_TEST(mtime(out / "variants/000/report.json") == t0);
  BOOST_TEST(mtime(out / "variants/001/report.json") != t1);
  rows = read_results(out / "results.csv");
  BOOST_TEST(rows[1].at("wall") == "1");

  // --collect merges the same table from the variants' files.
  const std::string merged = read_text(out / "results.csv");
  fs::remove(out / "results.csv");
  const test::Run collect = test::run_cli("sweep --collect " + q(out), dir.path);
  BOOST_TEST(collect.exit_code == 0, collect.err);
  BOOST_TEST(read_text(out / "results.csv") == merged);

  // --emit slurm: a job array of --only tasks; --only of an up-to-date variant runs nothing.
  const test::Run emit = test::run_cli("sweep " + q(study) + " -o " + q(out) + " --emit slurm --jobs 2", dir.path);
  BOOST_TEST(emit.exit_code == 0, emit.err);
  const std::string sbatch = read_text(out / "study.sbatch");
  BOOST_TEST(contains(sbatch, "#SBATCH --array=0-2%2\n"), sbatch);
  BOOST_TEST(contains(sbatch, " sweep " + q(study) + " -o " + q(out) + " --only \"$SLURM_ARRAY_TASK_ID\""), sbatch);
  const test::Run only = test::run_cli("sweep " + q(study) + " -o " + q(out) + " --only 1", dir.path);
  BOOST_TEST(only.exit_code == 0, only.err);
  BOOST_TEST(contains(only.out, "1 variants (1 built); 0 run now, 1 up to date"), only.out);
  const test::Run bad_only = test::run_cli("sweep " + q(study) + " -o " + q(out) + " --only 7", dir.path);
  BOOST_TEST(bad_only.exit_code == 2, bad_only.err);
  BOOST_TEST(contains(bad_only.err, "--only: '7' is not a variant of the study (index 0 to 2 or id 000 to 002)"), bad_only.err);
}

// A variant that outlives --timeout is a timeout row (the build stops itself: exit 6); the study goes on.
BOOST_AUTO_TEST_CASE(timeout_is_a_row) {
  TempDir dir("study_timeout");
  write(dir.path / "study.json", study_text());
  write(dir.path / "rows.csv", "rib_ss,wall,stagger\n0.46,1.0,0\n0.46,60,0\n");
  const test::Run r = test::run_cli("sweep " + q(dir.path / "study.json") + " -o " + q(dir.path / "out") + " --timeout 0.2", dir.path);
  BOOST_TEST(r.exit_code == 0, r.err);
  const auto rows = read_results(dir.path / "out/results.csv");
  BOOST_TEST_REQUIRE(rows.size() == 2u);
  BOOST_TEST(rows[0].at("status") == "timeout");
  BOOST_TEST(rows[0].at("exit_code") == "6");
  BOOST_TEST(rows[0].at("error").rfind("time limit of 0.2 s reached: stopped", 0) == 0u, rows[0].at("error"));
  BOOST_TEST(rows[1].at("status") == "refused");
  BOOST_TEST(std::stod(rows[0].at("process_s")) > 0.2);
  BOOST_TEST(rows[1].at("process_s").empty());  // refused before any process

  // A timeout is run again; a refusal by the build (exit 2, recorded with the same input hash) is not.
  const std::string rerun = "sweep " + q(dir.path / "study.json") + " -o " + q(dir.path / "out") + " --timeout 0.2";
  const test::Run again = test::run_cli(rerun, dir.path);
  BOOST_TEST(contains(again.out, "1 run now, 0 up to date"), again.out);
  const fs::path status = dir.path / "out/variants/000/status.json";
  json st = json::parse(read_text(status));
  BOOST_TEST(st["status"] == "timeout");
  st["status"] = "refused", st["exit_code"] = 2, st["error"] = "cooling.core: refused by the build";
  write(status, st.dump());
  const test::Run kept = test::run_cli(rerun, dir.path);
  BOOST_TEST(contains(kept.out, "0 run now, 1 up to date"), kept.out);
  BOOST_TEST(read_results(dir.path / "out/results.csv")[0].at("error") == "cooling.core: refused by the build");
}

// The process pool on stand-in programs whose behaviour is certain: a hang is killed at its limit, a
// crash is reported with its signal, an exit code passes through, at most `jobs` run at once, and a
// stop request interrupts the running ones and starts no more.
BOOST_AUTO_TEST_CASE(process_pool_outcomes) {
  TempDir dir("study_pool");
  const auto spec = [&](const std::string& script, double kill_after = 0) {
    study::ProcessSpec s;
    s.argv = {"/bin/sh", "-c", script};
    s.stdout_file = dir.path / "out.txt";
    s.stderr_file = dir.path / "err.txt";
    s.kill_after_s = kill_after;
    return s;
  };
  study::PoolOptions o;
  o.jobs = 2;
  int finished = 0;
  o.on_finished = [&](std::size_t, const study::ProcessResult&) { ++finished; };
  const auto t0 = std::chrono::steady_clock::now();
  const auto r = study::run_processes({spec("exec sleep 30", 0.3), spec("kill -SEGV $$"), spec("exit 3")}, o);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  BOOST_TEST(finished == 3);
  BOOST_TEST(r[0].killed_for_time);
  BOOST_TEST(r[0].signal == SIGKILL);
  BOOST_TEST(r[1].signal == SIGSEGV);
  BOOST_TEST(r[1].exit_code == -1);
  BOOST_TEST(!r[1].killed_for_time);
  BOOST_TEST(r[2].exit_code == 3);
  BOOST_TEST(seconds < 10, seconds);  // the 30 s hang did not hold the pool (limit 0.3 s, polling 20 ms)

  // A spec waiting for an earlier one starts when that one created its ready_path, not at its end
  // (the stage cache's entry); without a ready_path, at its end.
  std::vector<std::size_t> order;
  o.on_finished = [&](std::size_t i, const study::ProcessResult&) { order.push_back(i); };
  const fs::path ready = dir.path / "entry";
  for (const bool with_path : {true, false}) {
    fs::remove_all(ready);
    order.clear();
    std::vector<study::ProcessSpec> specs{spec("mkdir " + q(ready) + " && exec sleep 2"), spec("exit 0")};
    if (with_path) specs[0].ready_path = ready;
    specs[1].after = 0;
    study::run_processes(specs, o);
    BOOST_TEST((order == std::vector<std::size_t>{with_path ? 1u : 0u, with_path ? 0u : 1u}), with_path);
  }
  o.on_finished = {};

  // Stop after 0.3 s: the two running sleeps get SIGINT, the third never starts.
  o.stop_requested = [t0 = std::chrono::steady_clock::now()] {
    return std::chrono::steady_clock::now() - t0 > std::chrono::milliseconds(300);
  };
  const auto s = study::run_processes({spec("exec sleep 30"), spec("exec sleep 30"), spec("exec sleep 30")}, o);
  BOOST_TEST(s[0].interrupted);
  BOOST_TEST(s[0].signal == SIGINT);
  BOOST_TEST(s[1].signal == SIGINT);
  BOOST_TEST(!s[2].started);
}

// The base inline or by a path relative to the study file, a grid's order (the last parameter fastest)
// and "outputs" mapped onto the variant's output formats; --emit slurm checks and writes the variants
// without building any.
BOOST_AUTO_TEST_CASE(bases_grid_and_outputs) {
  TempDir dir("study_bases");
  fs::create_directories(dir.path / "configs");
  json base = json::parse(read_text(kBase));
  base["output"]["step_schema"] = "AP214";
  write(dir.path / "configs/base.json", base.dump());
  json s{{"base", "configs/base.json"},
         {"parameters",
          {{{"path", "cooling.core.ribs[0].suction_chord"}, {"values", {0.44, 0.48}}},
           {{"path", "cooling.core.wall_thickness"}, {"range", {0.9, 1.1}}, {"levels", 3}}}},
         {"design", {{"type", "grid"}}},
         {"outputs", {"step", "stl"}}};
  write(dir.path / "by_path.json", s.dump());
  s["base"] = base;
  write(dir.path / "inline.json", s.dump());
  for (const char* name : {"by_path", "inline"}) {
    const fs::path out = dir.path / (std::string(name) + "_out");
    const test::Run r = test::run_cli("sweep " + q(dir.path / (std::string(name) + ".json")) + " -o " + q(out) + " --emit slurm", dir.path);
    BOOST_TEST_REQUIRE(r.exit_code == 0, r.err);
    BOOST_TEST(contains(r.out, "(6 array tasks, 6 pending)"), r.out);
    BOOST_TEST(contains(read_text(out / "study.sbatch"), "#SBATCH --array=0-5%"));
    const double expect[6][2] = {{0.44, 0.9}, {0.44, 1.0}, {0.44, 1.1}, {0.48, 0.9}, {0.48, 1.0}, {0.48, 1.1}};
    for (int i = 0; i < 6; ++i) {
      const fs::path vdir = out / "variants" / ("00" + std::to_string(i));
      const json c = json::parse(read_text(vdir / "config.json"));
      BOOST_TEST(c["cooling"]["core"]["ribs"][0]["suction_chord"].get<double>() == expect[i][0]);
      BOOST_TEST(std::abs(c["cooling"]["core"]["wall_thickness"].get<double>() - expect[i][1]) < 1e-15);  // 0.9 + 0.2 * i / 2
      BOOST_TEST(c["output"]["formats"] == json({"step", "stl"}));
      BOOST_TEST(c["output"]["step_schema"] == "AP214");  // the base's other output options stay
      BOOST_TEST(!fs::exists(vdir / "report.json"));
    }
  }
}
