// coolinggen.build / validate / example and the Result class: the jobs of `coolinggen build` and
// `coolinggen validate` (src/cli/command_build.cpp, command_validate.cpp) on the pipeline library.
#include <pybind11/stl.h>

#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_Printer.hxx>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <mutex>
#include <sstream>

#include "export/version.hpp"
#include "python/src/bind.hpp"
#include "python/src/build_job.hpp"
#include "python/src/config_input.hpp"
#include "python/src/errors.hpp"
#include "src/config/builtin_example.hpp"
#include "src/config/config_error.hpp"
#include "src/pipeline/build.hpp"
#include "src/pipeline/handoff_formats.hpp"
#include "src/pipeline/outputs.hpp"
#include "src/pipeline/report.hpp"
#include "src/pipeline/time_limit.hpp"
#include "export/atomic_file.hpp"

namespace py = pybind11;
namespace fs = std::filesystem;

namespace cg::python {
namespace {

py::object json_module() { return py::module_::import("json"); }

py::object to_python(const nlohmann::ordered_json& j) { return json_module().attr("loads")(j.dump()); }

// `outputs` of build(): None keeps the config's output.formats; "none" or [] writes report.json only;
// a str or a list of str names the formats (checked like output.formats).
void apply_outputs(config::Config& c, const py::handle& outputs) {
  if (outputs.is_none()) return;
  std::vector<std::string> formats;
  if (PyUnicode_Check(outputs.ptr())) {
    const std::string s = outputs.cast<std::string>();
    if (s != "none") formats.push_back(s);
  } else if (PyList_Check(outputs.ptr()) || PyTuple_Check(outputs.ptr())) {
    for (const py::handle f : outputs) {
      if (!PyUnicode_Check(f.ptr()))
        throw config::ConfigError("outputs: must be None, \"none\" or a list of format names (str), got an item of type " +
                                  std::string(Py_TYPE(f.ptr())->tp_name));
      formats.push_back(f.cast<std::string>());
    }
  } else {
    throw config::ConfigError("outputs: must be None, \"none\", a format name or a list of format names, got " +
                              std::string(Py_TYPE(outputs.ptr())->tp_name));
  }
  c.output.formats = config::parse_output_formats(formats, "output.formats");
  c.source["output"]["formats"] = formats;  // the report's copy of the config says what was asked
}

double timeout_seconds(const py::handle& timeout) {
  if (timeout.is_none()) return 0;
  if (PyBool_Check(timeout.ptr()) || !(PyFloat_Check(timeout.ptr()) || PyLong_Check(timeout.ptr())))
    throw config::ConfigError("timeout: must be None or a number of seconds > 0, got " +
                              std::string(Py_TYPE(timeout.ptr())->tp_name));
  const double s = timeout.cast<double>();
  if (!(s > 0) || !std::isfinite(s))
    throw config::ConfigError("timeout: must be None or a number of seconds > 0, got " + py::str(timeout).cast<std::string>());
  return s;
}

// Runs `job` released from the GIL with progress and an optional time limit; a stop becomes Cancelled
// "<reason>: stopped in <where><after>" (the CLI's message), the library's model errors FeatureFailure.
void run_job(PythonProgress& progress, double timeout_s, const std::string& after,
             const std::function<void(ProgressSink*)>& job) {
  // One job at a time per process: the library makes no promise for concurrent builds in one process
  // (parallel builds: coolinggen.study, one process each). Taken on the worker thread, without the GIL.
  static std::mutex one_job;
  pipeline::TimeLimit limit(&progress, timeout_s);
  try {
    run_released(progress, [&] {
      std::lock_guard<std::mutex> lock(one_job);
      job(&limit);
    });
  } catch (const Cancelled& e) {
    throw CancelledError(limit.stop_reason() + ": " + e.what() + after);  // what(): "stopped ..."
  } catch (const config::ConfigError&) {
    throw;
  } catch (const io::ExportError&) {
    throw;
  } catch (const InvalidGeometry& e) {
    throw FeatureFailureError(e.what());
  } catch (const AlgorithmFailure& e) {
    throw FeatureFailureError(e.what());
  }
}

struct Built {
  config::Config config;
  pipeline::BuildResult result;
  py::object report;  // the build's report (outputs: none written yet), then the last written one
};

std::vector<std::string> failed_checks(const pipeline::BuildResult& r) {
  std::vector<std::string> out;
  for (std::size_t i = 0; i < r.checks.size() && i < r.part.size(); ++i)
    for (const brep::Check* k : r.checks[i].checks())
      if (!k->passed) out.push_back(r.part[i].name + ": " + k->name);
  if (r.checks.size() != r.part.size()) out.push_back("not every body was checked");
  return out;
}

py::object build_report(const Built& b) {
  io::ReportContent rc = pipeline::report_content(b.config, b.result, {}, b.result.timings);
  pipeline::add_handoff_report(b.config, b.result, rc);
  return to_python(io::report_json(rc));
}

std::shared_ptr<Built> build(const py::handle& config, const py::handle& outputs, const py::handle& timeout,
                             const py::object& progress_callback) {
  auto b = std::make_shared<Built>();
  b->config = load_config(config);
  apply_outputs(b->config, outputs);
  PythonProgress progress(progress_callback);
  run_job(progress, timeout_seconds(timeout), "; nothing built",
          [&](ProgressSink* sink) { b->result = pipeline::run_build(b->config, {}, sink); });
  b->report = build_report(*b);
  return b;
}

// Result.write(dir): write_outputs with the CLI's rules (atomic files, report.json last, this run's
// files removed again when it fails or stops). Returns the names written, report.json last.
std::vector<std::string> write(Built& b, const py::handle& directory, const py::object& progress_callback) {
  const fs::path dir = py::module_::import("os").attr("fspath")(directory).cast<std::string>();
  std::error_code ec;
  if (fs::exists(dir, ec) && !fs::is_directory(dir, ec))
    throw io::ExportError("output directory " + dir.string() + " exists and is not a directory");
  PythonProgress progress(progress_callback);
  pipeline::WrittenOutputs w;
  run_job(progress, 0, "; the outputs of this run were removed, " + dir.string() + " holds none",
          [&](ProgressSink* sink) { w = pipeline::write_outputs(b.config, b.result, dir, sink); });
  std::ifstream in(dir / pipeline::kReportFile);
  std::stringstream text;
  text << in.rdbuf();
  b.report = json_module().attr("loads")(text.str());
  return w.files;
}

py::dict validate(const py::handle& config, const py::object& progress_callback) {
  const config::Config c = load_config(config);
  PythonProgress progress(progress_callback);
  pipeline::Validation v;
  run_job(progress, 0, "", [&](ProgressSink* sink) { v = pipeline::validate(c, sink); });
  py::dict d;
  d["name"] = c.name;
  d["flow_path"] = v.model.trim.straight ? "straight" : "meridional";
  d["sections"] = config::section_count(c);
  d["notes"] = v.notes;
  return d;
}

}  // namespace

void bind_build(py::module_& m) {
  // OCCT's data exchange prints transfer statistics through the default messenger (as src/cli/main.cpp).
  for (const Handle(Message_Printer)& p : Message::DefaultMessenger()->Printers()) p->SetTraceLevel(Message_Fail);
  m.attr("__version__") = io::tool_version();

  py::class_<Built, std::shared_ptr<Built>>(m, "Result", "A built and checked model (coolinggen.build).")
      .def_property_readonly("valid", [](const Built& b) { return b.result.valid(); },
                             "Every check of every body passed.")
      .def_property_readonly("failed_checks", [](const Built& b) { return failed_checks(b.result); },
                             "The failed checks as 'body: check' (empty when valid).")
      .def_property_readonly("report", [](const Built& b) { return b.report; },
                             "The report (report.json) as a dict; after write() the written one.")
      .def_property_readonly("warnings", [](const Built& b) { return b.result.warnings; })
      .def_property_readonly("name", [](const Built& b) { return b.config.name; })
      .def("write", &write, py::arg("directory"), py::arg("progress") = py::none(),
           "Writes the outputs into `directory` (created if missing) as `coolinggen build -o` does: the "
           "config's formats and report.json last when valid, report.json alone when a check failed; "
           "earlier outputs there are removed first, and this run's again if writing fails. Returns the "
           "file names written.")
      .def("__repr__", [](const Built& b) {
        return "<coolinggen.Result " + b.config.name + (b.result.valid() ? " valid>" : " INVALID>");
      });

  m.def("build", &build, py::arg("config"), py::arg("outputs") = py::none(), py::arg("timeout") = py::none(),
        py::arg("progress") = py::none(),
        "Builds and checks the model of `config` (dict, JSON text or path). outputs: None (the config's "
        "output.formats), 'none' or [] (report.json only), or a list of formats, for Result.write. timeout: "
        "seconds (raises Cancelled). progress: callable(stage, fraction, step). Ctrl-C stops the build "
        "(Cancelled). Failed checks do not raise: see Result.valid.");
  m.def("validate", &validate, py::arg("config"), py::arg("progress") = py::none(),
        "What `coolinggen validate` checks (config, blade model, cooling input), without the solid. "
        "Returns {'name', 'flow_path', 'sections', 'notes'} (notes: what the cooling plan changed, e.g. a wall thickened toward the TE for a cutback); raises ConfigError.");
  m.def("example", [] { return json_module().attr("loads")(config::builtin_example_json()); },
        "The built-in example config (data/examples/hpt_rotor.json) as a dict.");
}

}  // namespace cg::python
