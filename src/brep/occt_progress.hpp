#pragma once
// Bridge from OCCT's progress protocol to cg::ProgressSink: OCCT algorithms that take a
// Message_ProgressRange (BOPAlgo_Builder::Perform, BRepAlgoAPI_*::Build, BRepMesh_IncrementalMesh)
// report their position through Show() and poll UserBreak(), which here asks the sink. A stopped OCCT
// algorithm returns early with an incomplete result, so the caller must call throw_if_stopped()
// right after it and before looking at the result.
#include <Message_ProgressIndicator.hxx>

#include <atomic>
#include <string>

#include "src/core/progress.hpp"

namespace cg::brep {

class OcctProgress : public Message_ProgressIndicator {
 public:
  /// `sink` may be null (then nothing is reported and OCCT is never stopped); `step` names the
  /// algorithm in progress messages and in Cancelled ("general fuse").
  OcctProgress(ProgressSink* sink, std::string step) : sink_(sink), step_(std::move(step)) {}

  /// Throws Cancelled(step) when UserBreak() has told OCCT to stop.
  void throw_if_stopped() const {
    if (stopped_) throw Cancelled(step_);
  }

  Standard_Boolean UserBreak() override {
    if (sink_ && sink_->stop_requested()) stopped_ = true;
    return stopped_;
  }
  void Show(const Message_ProgressScope&, const Standard_Boolean) override {
    if (sink_) sink_->stage_progress(GetPosition(), step_);
  }

 private:
  ProgressSink* sink_;
  std::string step_;
  std::atomic<bool> stopped_{false};  // UserBreak runs on OCCT's worker threads
};

}  // namespace cg::brep
