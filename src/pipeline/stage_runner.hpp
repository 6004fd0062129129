#pragma once
// Runs the named stages of a job: announces each to the progress sink, polls for a stop request
// before it, times it, and turns a Cancelled from inside it into one that names the stage.
#include <functional>
#include <string>
#include <vector>

#include "src/core/progress.hpp"
#include "src/pipeline/stage_records.hpp"

namespace cg::pipeline {

class StageRunner {
 public:
  /// Timings of the stages run are appended to `timings`; `sink` may be null.
  StageRunner(ProgressSink* sink, std::vector<StageTiming>& timings) : sink_(sink), timings_(&timings) {}

  /// Runs `body` as stage `stage` ("solid"; `title` is for people: "solid (trim to the flow path)").
  /// Throws Cancelled("before stage 'solid'", "stage 'solid', at general fuse") when the sink asks to
  /// stop before or inside it;
  /// other exceptions pass unchanged.
  void run(const std::string& stage, const std::string& title, const std::function<void()>& body);

  ProgressSink* sink() const { return sink_; }

 private:
  ProgressSink* sink_;
  std::vector<StageTiming>* timings_;
};

}  // namespace cg::pipeline
