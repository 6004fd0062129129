#pragma once
// Stage progress and cooperative cancellation, shared by every stage (standard library only).
//
// A caller hands a ProgressSink to long computations. They report how far they are and poll
// check_cancel() between steps; OCCT algorithms get a Message_ProgressRange bridged to the same sink
// (src/brep/occt_progress.hpp), whose UserBreak() makes OCCT stop. A stop is never forced: the
// computation unwinds with Cancelled from its next check point, so no half-made result or file is
// left. The pipeline (src/pipeline) names and times the stages and adds the stage to the message.
#include <string>

#include "src/core/error.hpp"

namespace cg {

/// A computation stopped because its ProgressSink asked it to (time limit, user break).
/// where() names the place ("general fuse", "stage 'verify', at closed_mesh"); what() is
/// "stopped in <where>" (or "stopped before <where>" when the stop came before that step began).
class Cancelled : public Error {
 public:
  explicit Cancelled(const std::string& where, const char* preposition = "in")
      : Error("stopped " + std::string(preposition) + " " + where), where_(where) {}
  const std::string& where() const { return where_; }

 private:
  std::string where_;
};

/// Receives progress and answers whether to stop. Every member has a do-nothing default, so a sink
/// implements only what it needs. Implementations must be thread-safe: OCCT's parallel algorithms
/// report and poll from worker threads.
class ProgressSink {
 public:
  virtual ~ProgressSink() = default;
  /// A stage begins: `stage` is its stable id ("solid"), `title` a short text for people.
  virtual void stage_started(const std::string& stage, const std::string& title) {
    (void)stage;
    (void)title;
  }
  /// Fraction in [0, 1] of the current stage done; `step` names the running sub-step ("general fuse").
  virtual void stage_progress(double fraction, const std::string& step) {
    (void)fraction;
    (void)step;
  }
  /// The stage ended successfully after `seconds` (wall clock).
  virtual void stage_finished(const std::string& stage, double seconds) {
    (void)stage;
    (void)seconds;
  }
  /// Polled by long computations; true makes them stop at their next check point. Must be cheap.
  virtual bool stop_requested() const { return false; }
  /// Why a stop was requested, for the message ("time limit of 60 s reached").
  virtual std::string stop_reason() const { return "stop requested"; }
};

/// Poll point: throws Cancelled(where) when `sink` asks to stop. A null sink never stops.
inline void check_cancel(const ProgressSink* sink, const std::string& where) {
  if (sink && sink->stop_requested()) throw Cancelled(where);
}

/// Reports `fraction` of the current stage to `sink` (null: nothing).
inline void report_progress(ProgressSink* sink, double fraction, const std::string& step) {
  if (sink) sink->stage_progress(fraction, step);
}

}  // namespace cg
