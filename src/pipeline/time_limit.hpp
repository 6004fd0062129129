#pragma once
// A wall-clock limit for a job: wraps a progress sink and asks the job to stop once the time is up.
#include <string>

#include "src/core/progress.hpp"

namespace cg::pipeline {

/// A sink that forwards everything to `inner` (may be null) and also requests a stop once `seconds`
/// of wall-clock time have passed since it was made (seconds <= 0: no limit).
class TimeLimit : public ProgressSink {
 public:
  TimeLimit(ProgressSink* inner, double seconds);
  bool expired() const;
  double seconds() const { return seconds_; }

  void stage_started(const std::string& stage, const std::string& title) override;
  void stage_progress(double fraction, const std::string& step) override;
  void stage_finished(const std::string& stage, double seconds) override;
  bool stop_requested() const override;
  std::string stop_reason() const override;

 private:
  ProgressSink* inner_;
  double seconds_;
  double start_;  // steady clock, seconds
};

}  // namespace cg::pipeline
