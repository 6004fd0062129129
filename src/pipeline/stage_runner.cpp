#include "src/pipeline/stage_runner.hpp"

#include <chrono>

namespace cg::pipeline {
namespace {

double now_s() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

}  // namespace

void StageRunner::run(const std::string& stage, const std::string& title, const std::function<void()>& body) {
  const std::string where = "stage '" + stage + "'";
  if (sink_ && sink_->stop_requested()) throw Cancelled(where, "before");
  if (sink_) sink_->stage_started(stage, title);
  const double t0 = now_s();
  try {
    body();
  } catch (const Cancelled& e) {
    throw Cancelled(e.where() == stage ? where : where + ", at " + e.where());
  }
  const double seconds = now_s() - t0;
  timings_->push_back({stage, seconds});
  if (sink_) sink_->stage_finished(stage, seconds);
}

}  // namespace cg::pipeline
