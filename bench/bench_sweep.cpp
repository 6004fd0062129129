// bench_sweep: a design study's wall time against the serial sum of its variants' process wall times
// (measured in the same run), the parallel gain of `coolinggen sweep --jobs 2`; then the rerun, which
// must build nothing. Exit 1 when a variant is not built or the rerun builds one.
//
//   bench_sweep            data/studies/hpt_rotor_lhs24.json (24 variants of the built-in example;
//                          long: each variant is a full cooled build)
//   bench_sweep --quick    2 variants of the light study config of tests/study (two-pass core, one rib)
//   bench_sweep STUDY      any study file
// Runs the coolinggen binary of the build directory (each variant is a `coolinggen build` process).
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>

#include "src/study/sweep.hpp"

namespace fs = std::filesystem;
using namespace cg;

namespace {

std::string quick_study(const fs::path& dir) {
  const fs::path study = dir / "quick_study.json";
  std::ofstream(study) << R"({"name": "bench_quick", "base": ")" COOLINGGEN_SOURCE_DIR R"(/tests/study/light_base.json",
 "parameters": [{"path": "cooling.core.wall_thickness", "values": [0.9, 1.1]}], "design": {"type": "grid"}})";
  return study.string();
}

}  // namespace

int main(int argc, char** argv) {
  const bool quick = argc > 1 && std::strcmp(argv[1], "--quick") == 0;
  const fs::path work = fs::temp_directory_path() / ("cg_bench_sweep_" + std::to_string(::getpid()));
  fs::remove_all(work);
  fs::create_directories(work);
  study::SweepOptions o;
  o.study_file = quick ? quick_study(work) : argc > 1 ? argv[1] : COOLINGGEN_SOURCE_DIR "/data/studies/hpt_rotor_lhs24.json";
  o.output = work / "study";
  o.executable = fs::path(COOLINGGEN_BINARY_DIR) / "coolinggen";
  o.jobs = 2;
  int failures = 0;
  try {
    const study::SweepOutcome first = study::run_sweep(o);
    // The serial sum: the wall time of every variant's process (built, or refused or failed by the
    // build after part of it), each measured while sharing the machine with the other job.
    double serial = 0, built_s = 0;
    int built = 0, ran = 0;
    for (const study::ResultRow& r : first.listing.rows) {
      if (r.process_s) ++ran, serial += *r.process_s;
      if (r.status == study::Status::kBuilt) ++built, built_s += r.metrics.build_s.value_or(0);
      else if (r.status != study::Status::kRefused) ++failures, std::printf("NOT BUILT: variant %s: %s %s\n", r.id.c_str(), study::status_name(r.status), r.error.c_str());
    }
    std::printf("%s: %zu variants, %d built, %d processes, --jobs 2: wall %.1f s, serial sum of the processes' wall times %.1f s, "
                "ratio %.2f (goal >= 1.7); the built variants' build_s sum %.1f s\n",
                first.listing.name.c_str(), first.listing.rows.size(), built, ran, first.wall_s, serial, serial / first.wall_s, built_s);
    const study::SweepOutcome again = study::run_sweep(o);
    std::printf("rerun: %d built, %d up to date, wall %.2f s\n", again.ran, again.skipped, again.wall_s);
    if (again.ran != 0) ++failures, std::printf("RERUN BUILT %d variants\n", again.ran);
  } catch (const std::exception& e) {
    std::printf("bench_sweep: %s\n", e.what());
    ++failures;
  }
  fs::remove_all(work);
  std::printf("bench_sweep: %s\n", failures == 0 ? "every variant built, the rerun built none" : "FAILED");
  return failures == 0 ? 0 : 1;
}
