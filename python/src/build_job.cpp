#include "python/src/build_job.hpp"

#include <condition_variable>
#include <exception>
#include <thread>

namespace py = pybind11;

namespace cg::python {

PythonProgress::PythonProgress(py::object callback) : callback_(std::move(callback)) {
  if (callback_.is_none()) callback_ = py::object();
  else if (!PyCallable_Check(callback_.ptr()))
    throw py::type_error("progress must be None or a callable progress(stage, fraction, step), got " +
                         std::string(Py_TYPE(callback_.ptr())->tp_name));
}

PythonProgress::~PythonProgress() {
  Py_XDECREF(error_type_);
  Py_XDECREF(error_value_);
  Py_XDECREF(error_trace_);
}

void PythonProgress::request_stop(const std::string& reason) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!stop_) reason_ = reason;
  stop_ = true;
}

std::string PythonProgress::stop_reason() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return stop_ ? reason_ : "stop requested";
}

void PythonProgress::call(const std::string& stage, double fraction, const std::string& step) {
  if (!callback_ || stop_) return;
  py::gil_scoped_acquire gil;
  if (stop_) return;
  try {
    callback_(stage, fraction, step);
  } catch (py::error_already_set& e) {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!error_type_) {
      e.restore();  // back to the interpreter's error indicator, then kept for rethrow_callback_error
      PyErr_Fetch(&error_type_, &error_value_, &error_trace_);
    }
    if (!stop_) reason_ = "the progress callback raised an exception";
    stop_ = true;
  }
}

void PythonProgress::stage_started(const std::string& stage, const std::string& title) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stage_ = stage;
    last_call_ = std::chrono::steady_clock::now();
  }
  call(stage, 0.0, title);
}

void PythonProgress::stage_progress(double fraction, const std::string& step) {
  if (!callback_) return;
  std::string stage;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    const auto now = std::chrono::steady_clock::now();
    if (now - last_call_ < std::chrono::milliseconds(100)) return;
    last_call_ = now;
    stage = stage_;
  }
  call(stage, fraction, step);
}

void PythonProgress::stage_finished(const std::string& stage, double) { call(stage, 1.0, "done"); }

void PythonProgress::rethrow_callback_error() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!error_type_) return;
  PyErr_Restore(error_type_, error_value_, error_trace_);
  error_type_ = error_value_ = error_trace_ = nullptr;
  throw py::error_already_set();
}

void run_released(PythonProgress& progress, const std::function<void()>& job) {
  std::mutex mutex;
  std::condition_variable finished;
  bool done = false;
  std::exception_ptr error;
  {
    py::gil_scoped_release release;
    std::thread worker([&] {
      try {
        job();
      } catch (...) {
        error = std::current_exception();
      }
      std::lock_guard<std::mutex> lock(mutex);
      done = true;
      finished.notify_all();
    });
    std::unique_lock<std::mutex> lock(mutex);
    while (!finished.wait_for(lock, std::chrono::milliseconds(50), [&] { return done; })) {
      lock.unlock();
      {
        py::gil_scoped_acquire gil;
        if (PyErr_CheckSignals() != 0) {  // a handler raised (KeyboardInterrupt): stop the job instead
          PyErr_Clear();
          progress.request_stop("interrupted (Ctrl-C)");
        }
      }
      lock.lock();
    }
    lock.unlock();
    worker.join();
  }
  progress.rethrow_callback_error();
  if (error) std::rethrow_exception(error);
}

}  // namespace cg::python
