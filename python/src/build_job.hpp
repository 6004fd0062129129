#pragma once
// Running a library job from Python: the job runs on a worker thread with the GIL released, while the
// calling thread waits and, every 50 ms, takes the GIL to check for signals (PyErr_CheckSignals: a
// Ctrl-C becomes a stop request, "interrupted (Ctrl-C)"). Progress goes to an optional Python
// callable progress(stage, fraction, step), called with the GIL held, at a stage's start (fraction 0,
// step = the stage's title), during it (at most every 0.1 s) and at its end (fraction 1, "done"). If
// the callback raises, the job is stopped and that exception is raised. The job stops cooperatively
// at its next check point (src/core/progress.hpp): Cancelled, which the caller turns into
// coolinggen.Cancelled with the reason.
#include <pybind11/pybind11.h>

#include <atomic>
#include <chrono>
#include <functional>
#include <mutex>
#include <string>

#include "src/core/progress.hpp"

namespace cg::python {

class PythonProgress : public ProgressSink {
 public:
  /// `callback`: None or a callable (stage, fraction, step).
  explicit PythonProgress(pybind11::object callback);
  ~PythonProgress() override;

  void stage_started(const std::string& stage, const std::string& title) override;
  void stage_progress(double fraction, const std::string& step) override;
  void stage_finished(const std::string& stage, double seconds) override;
  bool stop_requested() const override { return stop_; }
  std::string stop_reason() const override;

  void request_stop(const std::string& reason);
  /// Raises (as py::error_already_set) the exception the callback raised, if it did. GIL held.
  void rethrow_callback_error();

 private:
  void call(const std::string& stage, double fraction, const std::string& step);

  pybind11::object callback_;
  std::atomic<bool> stop_{false};
  mutable std::mutex mutex_;
  std::string reason_, stage_;
  std::chrono::steady_clock::time_point last_call_{};
  PyObject *error_type_ = nullptr, *error_value_ = nullptr, *error_trace_ = nullptr;
};

/// Runs `job` on a worker thread with the GIL released (the GIL must be held on entry) and waits,
/// turning Ctrl-C into progress.request_stop. Rethrows the job's exception; a stop caused by the
/// callback rethrows the callback's exception instead.
void run_released(PythonProgress& progress, const std::function<void()>& job);

}  // namespace cg::python
