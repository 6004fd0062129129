// Issue 22 section 2: the stage cache. The cooling stage's key (a cooling.core field changes it, film
// fields do not), the store itself (memory, disk, an entry that is not whole), in-process builds with the
// memory cache against one without, and `coolinggen sweep` of three film-pitch variants of a light config
// with the disk cache and without: the same results.csv and report.json but for timings, the second and
// third variants taking the cooling stage from the cache. About 35 s of CPU.
#define BOOST_TEST_MODULE stage_cache
#include <boost/test/unit_test.hpp>

#include <cstdlib>
#include <filesystem>
#include <map>
#include <functional>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli/run_cli.hpp"
#include "support/ccx_run.hpp"
#include "src/config/config.hpp"
#include "src/pipeline/build.hpp"
#include "src/pipeline/cooling_stage_cache.hpp"
#include "src/pipeline/report.hpp"
#include "study/results_csv.hpp"

namespace fs = std::filesystem;
using namespace cg;
using nlohmann::json;
using test::q;
using test::read_text;
using test::TempDir;

namespace {

const fs::path kBase = COOLINGGEN_SOURCE_DIR "/tests/study/light_film_base.json";

// The light study base with one film row (~5 s a build, the cooling stage ~4 s, the film stage ~0.2 s),
// its pitch set.
json light_film(double pitch_d = 5) {
  std::ifstream in(kBase);
  json d = json::parse(in);
  d.erase("$schema");
  d["cooling"]["film_rows"][0]["pitch_d"] = pitch_d;
  return d;
}

config::Config parse(const json& d) { return config::parse_config(d, kBase.parent_path(), "light_film"); }

std::string key_of(const json& d) { return pipeline::cooling_stage_key(parse(d), features::Verification::FinalOnly); }

// A report without what may differ between equal builds: timings and the stage cache's own record.
json comparable(json r) {
  r.erase("timings_s");
  r.erase("stage_cache");
  if (r["model"].contains("cooling")) {
    r["model"]["cooling"].erase("seconds");
    if (r["model"]["cooling"].contains("film")) r["model"]["cooling"]["film"].erase("seconds");
  }
  return r;
}

json report_of(const config::Config& c, const pipeline::BuildResult& r) {
  return json::parse(io::report_json(pipeline::report_content(c, r, {"report.json"}, r.timings)).dump());
}

}  // namespace

// Strict key: every field the blade model, the solid or the cooling stage reads is in it.
BOOST_AUTO_TEST_CASE(key_covers_the_cooling_inputs_only) {
  const json base = light_film();
  const std::string k = key_of(base);
  BOOST_TEST(k.size() == 64u);
  BOOST_TEST(k == key_of(base));
  const auto changed = [&](const std::function<void(json&)>& edit) {
    json d = base;
    edit(d);
    return key_of(d) != k;
  };
  // Misses: the core, ribs, end walls, inlets, the blade, the booleans, the verification mode.
  BOOST_TEST(changed([](json& d) { d["cooling"]["core"]["wall_thickness"] = 1.1; }));
  BOOST_TEST(changed([](json& d) { d["cooling"]["core"]["ribs"][0]["fillet_radius"] = 0.4; }));
  BOOST_TEST(changed([](json& d) { d["cooling"]["core"]["tip_cap"]["thickness"] = 1.3; }));
  BOOST_TEST(changed([](json& d) { d["cooling"]["core"]["inlets"][1]["diameter"] = 2.4; }));
  BOOST_TEST(changed([](json& d) { d["sections"][1]["parametric"]["stagger_deg"] = -26.5; }));
  BOOST_TEST(changed([](json& d) { d["blade"]["chordwise_samples"] = 101; }));
  BOOST_TEST(changed([](json& d) { d["booleans"] = {{"allow_perturbation", false}}; }));
  BOOST_TEST(pipeline::cooling_stage_key(parse(base), features::Verification::EachStep) != k);
  // Hits: the film rows, the name, the outputs.
  BOOST_TEST(!changed([](json& d) { d["cooling"]["film_rows"][0]["pitch_d"] = 6; }));
  BOOST_TEST(!changed([](json& d) { d["cooling"]["film_rows"][0]["inclination_deg"] = 30; }));
  BOOST_TEST(!changed([](json& d) { d["cooling"].erase("film_rows"); }));
  BOOST_TEST(!changed([](json& d) { d["name"] = "other"; }));
  BOOST_TEST(!changed([](json& d) { d["output"]["formats"] = json::array({"step"}); }));
}

// The store: memory entries, disk entries read by another cache object, an entry that is not whole
// is removed and counts as absent, "memory" never touches the disk.
BOOST_AUTO_TEST_CASE(store_in_memory_and_on_disk) {
  TempDir dir("stage_cache_store");
  const std::string key(64, 'a');
  pipeline::StageCacheEntry e{std::string("\0shapes\1", 8), {{"format", "x"}, {"n", 1.5}}};
  pipeline::StageCache memory({pipeline::StageCacheMode::kMemory, dir.path / "m"});
  BOOST_TEST(!memory.find("cooling", key).get());
  memory.store("cooling", key, e);
  BOOST_TEST_REQUIRE(memory.find("cooling", key).get());
  BOOST_TEST(memory.find("cooling", key)->shapes == e.shapes);
  BOOST_TEST(!fs::exists(dir.path / "m"));
  pipeline::StageCache disk({pipeline::StageCacheMode::kDisk, dir.path / "d"});
  disk.store("cooling", key, e);
  const fs::path entry = disk.entry_directory("cooling", key);
  BOOST_TEST(fs::exists(entry / "shapes.bin"));
  BOOST_TEST(fs::exists(entry / "stage.json"));
  pipeline::StageCache other({pipeline::StageCacheMode::kDisk, dir.path / "d"});
  const auto found = other.find("cooling", key);
  BOOST_TEST_REQUIRE(found.get());
  BOOST_TEST(found->shapes == e.shapes);
  BOOST_TEST(found->data.at("n").get<double>() == 1.5);
  std::size_t names = 0;  // no temporary directory left beside the entry
  for (const auto& f : fs::directory_iterator(entry.parent_path())) names += f.path().filename().string()[0] == '.' ? 100 : 1;
  BOOST_TEST(names == 1u);
  std::ofstream(entry / "stage.json") << "{\"key\": \"trunc";
  pipeline::StageCache third({pipeline::StageCacheMode::kDisk, dir.path / "d"});
  BOOST_TEST(!third.find("cooling", key).get());
  BOOST_TEST(!fs::exists(entry));
  BOOST_CHECK_THROW(pipeline::parse_stage_cache_mode("ram", "--stage-cache"), config::ConfigError);
}

// In one process with the memory cache: the second variant takes the cooling stage from the first,
// and its report equals that of the same variant built without a cache.
BOOST_AUTO_TEST_CASE(memory_cache_in_process) {
  pipeline::StageCache cache({pipeline::StageCacheMode::kMemory, {}});
  pipeline::BuildOptions cached;
  cached.stage_cache = &cache;
  const config::Config a = parse(light_film(5)), b = parse(light_film(6));
  const pipeline::BuildResult ra = pipeline::run_build(a, cached);
  BOOST_TEST_REQUIRE(ra.stage_cache.size() == 1u);
  BOOST_TEST((ra.stage_cache[0].outcome == pipeline::StageCacheUse::Outcome::kStored));
  const pipeline::BuildResult rb = pipeline::run_build(b, cached);
  BOOST_TEST_REQUIRE(rb.stage_cache.size() == 1u);
  BOOST_TEST((rb.stage_cache[0].outcome == pipeline::StageCacheUse::Outcome::kHit));
  BOOST_TEST(rb.valid());
  const pipeline::BuildResult plain = pipeline::run_build(b);
  BOOST_TEST(plain.stage_cache.empty());
  BOOST_TEST_REQUIRE(plain.film.has_value());
  BOOST_TEST(plain.film->to_json().at("hole_count").get<int>() > 0);
  const json jb = report_of(b, rb), jp = report_of(b, plain);
  BOOST_TEST(jb.at("stage_cache").at(0).at("outcome") == "hit");
  BOOST_TEST(!jp.contains("stage_cache"));
  BOOST_TEST(comparable(jb) == comparable(jp));
  BOOST_TEST(comparable(report_of(a, ra)) != comparable(jp));  // the pitch shows in the report
  // The entry holds the passage report as report.json has it, and reads it back whole: stage times in
  // run order, the perturbed tools and the wall clearance included.
  BOOST_TEST_REQUIRE(plain.cooling.has_value());
  const nlohmann::ordered_json written = plain.cooling->to_json();
  const features::PassageReport back = features::PassageReport::from_json(written);
  BOOST_TEST(back.to_json().dump() == written.dump());
  BOOST_TEST_REQUIRE(back.seconds.size() == plain.cooling->seconds.size());
  for (std::size_t i = 0; i < back.seconds.size(); ++i) BOOST_TEST(back.seconds[i].first == plain.cooling->seconds[i].first);
  BOOST_TEST(!back.tools.empty());
}

// `coolinggen sweep` of three film pitches, two at a time, with the disk cache (default) and without.
BOOST_AUTO_TEST_CASE(sweep_with_and_without_the_cache) {
  TempDir dir("stage_cache_sweep");
  const json study{{"name", "film_pitch"},
                   {"base", light_film()},
                   {"parameters", {{{"name", "pitch"}, {"path", "cooling.film_rows[0].pitch_d"}, {"values", {5, 6, 7}}}}},
                   {"design", {{"type", "grid"}}}};
  std::ofstream(dir.path / "study.json") << study.dump(1);
  const fs::path on = dir.path / "on", off = dir.path / "off";
  test::Run r = test::run_cli("sweep " + q(dir.path / "study.json") + " -o " + q(on) + " --jobs 2 -q", dir.path);
  BOOST_TEST_REQUIRE(r.exit_code == 0, r.err);
  r = test::run_cli("sweep " + q(dir.path / "study.json") + " -o " + q(off) + " --jobs 2 -q --stage-cache off", dir.path);
  BOOST_TEST_REQUIRE(r.exit_code == 0, r.err);
  BOOST_TEST(!fs::exists(off / "cache"));

  auto rows_on = test::read_results(on / "results.csv"), rows_off = test::read_results(off / "results.csv");
  BOOST_TEST_REQUIRE(rows_on.size() == 3u);
  for (auto* rows : {&rows_on, &rows_off})
    for (auto& row : *rows) {
      BOOST_TEST(row.at("status") == "built", row.at("error"));
      row.erase("build_s");
      row.erase("process_s");
    }
  BOOST_TEST((rows_on == rows_off));
  BOOST_TEST(rows_on[0].at("hole_count") != rows_on[2].at("hole_count"));

  // The first variant built and stored the cooling stage; the other two waited for it and took it.
  const char* outcomes[] = {"stored", "hit", "hit"};
  std::string key;
  for (int i = 0; i < 3; ++i) {
    const std::string id = "00" + std::to_string(i);
    const json a = json::parse(read_text(on / "variants" / id / "report.json")), b = json::parse(read_text(off / "variants" / id / "report.json"));
    BOOST_TEST_REQUIRE(a.contains("stage_cache"));
    BOOST_TEST(a["stage_cache"][0]["stage"] == "cooling");
    BOOST_TEST(a["stage_cache"][0]["outcome"] == outcomes[i], id);
    if (i == 0) key = a["stage_cache"][0]["key"];
    BOOST_TEST(a["stage_cache"][0]["key"] == key);
    BOOST_TEST(!b.contains("stage_cache"));
    BOOST_TEST(read_text(on / "variants" / id / "build.log").find(std::string("stage cache: cooling ") + outcomes[i]) != std::string::npos);
    json ca = comparable(a), cb = comparable(b);
    // The variant's config file is in its study directory.
    BOOST_TEST(ca["model"]["source"] == (on / "variants" / id / "config.json").string());
    ca["model"].erase("source");
    cb["model"].erase("source");
    BOOST_TEST(ca == cb, id);
    if (i > 0) BOOST_TEST(a["timings_s"]["cooling"].get<double>() < 0.2 * b["timings_s"]["cooling"].get<double>(), id);
  }
  BOOST_TEST(fs::exists(on / "cache" / "cooling" / key / "shapes.bin"));
}

// A sweep of the coolant's boundary conditions only (the network is not a geometry input; the study gives
// no outputs: the network is the default of a base with a coolant section): the cooling
// stage is built once and taken from the cache twice; every variant's network converges and the coolant
// flow grows with the supply pressure. One variant's network.inp is run again by ccx here (the light
// variant of docs/network.md's checks): converged, mass conserved at every node, the supply's flow equal
// to the exits', one element per film hole of the row, at least 9 segments per chamber.
BOOST_AUTO_TEST_CASE(coolant_sweep_reuses_the_cooling_stage_and_solves_each_network) {
  TempDir dir("stage_cache_coolant");
  json base = light_film();
  base["coolant"] = {{"supply", {{"total_pressure_pa", 2.0e6}, {"total_temperature_k", 850}}},
                     {"sinks", {{"static_pressure_pa", 1.3e6}}},
                     {"rotational_speed_rpm", 13000}};
  const json study{{"name", "supply_pressure"},
                   {"base", base},
                   {"parameters", {{{"name", "supply"}, {"path", "coolant.supply.total_pressure_pa"}, {"values", {1.8e6, 2.2e6, 2.6e6}}}}},
                   {"design", {{"type", "grid"}}}};
  std::ofstream(dir.path / "study.json") << study.dump(1);
  const test::Run r = test::run_cli("sweep " + q(dir.path / "study.json") + " -o " + q(dir.path / "out") + " --jobs 1 -q", dir.path);
  BOOST_TEST_REQUIRE(r.exit_code == 0, r.err);
  const auto rows = test::read_results(dir.path / "out" / "results.csv");
  BOOST_TEST_REQUIRE(rows.size() == 3u);
  const char* outcomes[] = {"stored", "hit", "hit"};
  double previous = 0;
  for (int i = 0; i < 3; ++i) {
    BOOST_TEST(rows[static_cast<std::size_t>(i)].at("status") == "built");
    BOOST_TEST(rows[static_cast<std::size_t>(i)].at("network_status") == "converged");
    const double flow = std::stod(rows[static_cast<std::size_t>(i)].at("coolant_mass_flow_kg_s"));
    BOOST_TEST(flow > previous, "variant " << i << ": " << flow << " kg/s after " << previous);
    previous = flow;
    const json rep = json::parse(read_text(dir.path / "out" / "variants" / ("00" + std::to_string(i)) / "report.json"));
    BOOST_TEST(rep["stage_cache"][0]["outcome"] == outcomes[i], i);
  }
  const fs::path inp = dir.path / "out" / "variants" / "000" / "network.inp";
  const test::DeckRead deck = test::read_deck(read_text(inp));
  const test::CcxRun run = test::run_ccx(inp);
  BOOST_TEST_REQUIRE(run.converged, run.log.substr(run.log.size() > 2000 ? run.log.size() - 2000 : 0));
  const test::NodeBalance bal = test::node_balance(deck, run);
  BOOST_TEST(bal.worst <= 1.0, "node imbalance " << bal.worst_relative);
  BOOST_TEST(bal.supply > 0);
  BOOST_TEST(std::abs(bal.supply - bal.exits) <= 1e-6 * bal.supply, bal.supply << " t/s in, " << bal.exits << " out");
  int holes = 0;
  std::map<std::string, int> segments;
  for (const auto& [id, type] : deck.type) {
    const std::string n = deck.name.count(id) ? deck.name.at(id) : "";
    holes += type == "ORIFICE MS_MS" && n.rfind("film_row_", 0) == 0;
    if (n.find("_seg_") != std::string::npos) ++segments[n.substr(0, n.find("_seg_"))];
  }
  BOOST_TEST(holes == std::stoi(rows[0].at("hole_count")));
  BOOST_TEST(segments.count("chamber_1") == 1u);  // chamber 2 has no exit: no flow, pruned (docs/network.md)
  for (const auto& [chamber, count] : segments) BOOST_TEST(count >= 9, chamber << ": " << count << " segments");

  // Without ccx on PATH (the cooling stage from the study's cache): built and written, exit 0, the
  // network's status "no_solver" in report.json and a warning on stderr, never a silent zero.
  const std::string path = std::getenv("PATH") ? std::getenv("PATH") : "";
  setenv("PATH", "/nonexistent", 1);
  const test::Run nosolver = test::run_cli("build " + q(dir.path / "out" / "variants" / "000" / "config.json") + " -o " +
                                               q(dir.path / "nosolver") + " -q --stage-cache " + q(dir.path / "out" / "cache"),
                                           dir.path);
  setenv("PATH", path.c_str(), 1);
  BOOST_TEST(nosolver.exit_code == 0, nosolver.err);
  BOOST_TEST(nosolver.err.find("warning: network: no CalculiX solver") != std::string::npos, nosolver.err);
  const json rep = json::parse(read_text(dir.path / "nosolver" / "report.json"));
  BOOST_TEST(rep["network"]["status"] == "no_solver", rep["network"].dump());
  BOOST_TEST(!rep["network"].contains("total_mass_flow_kg_s"));
}
