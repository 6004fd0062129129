#pragma once
// Records of the stages a job ran: their wall-clock times and what the stage cache did for them. Plain
// data, shared by the build (build_result.hpp), the stage runner and the jobs after a build (outputs,
// mesh, grid), so none of them depends on another for it.
#include <string>

namespace cg::pipeline {

/// Wall-clock time of one stage, seconds.
struct StageTiming {
  std::string stage;
  double seconds = 0;
};

/// What the stage cache did for one stage of a build.
struct StageCacheUse {
  enum class Outcome {
    kHit,        ///< taken from the cache
    kStored,     ///< built and stored
    kNotStored,  ///< built; storing failed (the warning says why)
  };
  std::string stage;
  std::string key;  ///< hex digest of the stage's inputs
  Outcome outcome = Outcome::kStored;
  static const char* name(Outcome o);  ///< "hit", "stored", "not_stored"
};

}  // namespace cg::pipeline
