#include "src/pipeline/time_limit.hpp"

#include <chrono>

#include "src/core/format.hpp"

namespace cg::pipeline {
namespace {

double now_s() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

}  // namespace

TimeLimit::TimeLimit(ProgressSink* inner, double seconds) : inner_(inner), seconds_(seconds), start_(now_s()) {}

bool TimeLimit::expired() const { return seconds_ > 0 && now_s() - start_ > seconds_; }

void TimeLimit::stage_started(const std::string& stage, const std::string& title) {
  if (inner_) inner_->stage_started(stage, title);
}
void TimeLimit::stage_progress(double fraction, const std::string& step) {
  if (inner_) inner_->stage_progress(fraction, step);
}
void TimeLimit::stage_finished(const std::string& stage, double seconds) {
  if (inner_) inner_->stage_finished(stage, seconds);
}
bool TimeLimit::stop_requested() const { return expired() || (inner_ && inner_->stop_requested()); }

std::string TimeLimit::stop_reason() const {
  if (expired()) return "time limit of " + format_number(seconds_) + " s reached";
  return inner_ ? inner_->stop_reason() : ProgressSink::stop_reason();
}

}  // namespace cg::pipeline
