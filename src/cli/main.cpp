// coolinggen: command-line front end.
//   coolinggen build [CONFIG] -o DIR   config (or the built-in example) -> DIR/blade.step + DIR/report.json
//   coolinggen validate CONFIG         parse and check the config (builds the blade model), writes nothing
//   coolinggen example                 prints the built-in example config
// Exit codes: 0 success, 1 command-line error, 2 invalid config, 3 model/solid failure (a failed check
// writes report.json but no STEP file), 4 output error, 5 unexpected error. Errors are one line on stderr.
#include <CLI/CLI.hpp>
#include <Message.hxx>
#include <Message_Messenger.hxx>
#include <Message_Printer.hxx>
#include <Standard_Failure.hxx>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <string>

#include "export/atomic_file.hpp"
#include "export/report.hpp"
#include "export/step_writer.hpp"
#include "src/brep/blade_solid.hpp"
#include "src/brep/verify.hpp"
#include "src/config/builtin_example.hpp"
#include "src/config/config.hpp"

namespace fs = std::filesystem;
using namespace cg;

namespace {

enum ExitCode { kOk = 0, kUsage = 1, kBadConfig = 2, kModelFailure = 3, kOutputFailure = 4, kUnexpected = 5 };

// Thrown when verification fails after report.json was written.
struct ChecksFailed : Error {
  using Error::Error;
};

int error_exit(int code, std::string message) {
  for (char& c : message)
    if (c == '\n' || c == '\r') c = ' ';
  std::cerr << "coolinggen: error: " << message << "\n";
  return code;
}

// OCCT's data exchange prints transfer statistics through the default messenger; keep stdout ours.
void silence_occt() {
  for (const Handle(Message_Printer)& p : Message::DefaultMessenger()->Printers()) p->SetTraceLevel(Message_Fail);
}

struct Stopwatch {
  std::chrono::steady_clock::time_point t0 = std::chrono::steady_clock::now();
  double lap() {
    const auto t = std::chrono::steady_clock::now();
    const double s = std::chrono::duration<double>(t - t0).count();
    t0 = t;
    return s;
  }
};

config::Config load(const std::string& path) {
  return path.empty() ? config::builtin_example_config() : config::load_config_file(path);
}

int run_validate(const std::string& path) {
  const config::Config c = load(path);
  const blade::BladeModel m = config::build_model(c);
  std::printf("%s: valid (%s flow path, %zu sections)\n", path.c_str(),
              m.trim.straight ? "straight" : "meridional", c.blade.sections.size());
  return kOk;
}

int run_build(const std::string& path, const fs::path& out_dir, bool quiet) {
  Stopwatch sw;
  nlohmann::ordered_json timings = nlohmann::ordered_json::object();  // stages in run order
  const config::Config c = load(path);
  timings["config"] = sw.lap();
  const blade::BladeModel model = config::build_model(c);
  timings["blade_model"] = sw.lap();
  const brep::BladeSolid solid = brep::build_blade_solid(model);
  timings["solid"] = sw.lap();
  io::ReportContent report;
  brep::NamedShape product{solid.solid, solid.faces};
  nlohmann::json cooling_report;
  if (!c.cooling.empty()) {
    // The cooling features verify the solid after their last boolean step.
    features::PassagesResult cooled = config::apply_cooling(c.cooling, model, product);
    product = cooled.blade;
    report.check = cooled.check;
    cooling_report = cooled.report.to_json();
    timings["cooling"] = sw.lap();
  } else {
    report.check = brep::verify_solid(solid.solid);
    timings["verify"] = sw.lap();
  }
  for (const auto& f : product.faces) ++report.face_names[f.name];
  report.warnings = solid.warnings;
  report.model = config::model_summary(c, model);
  report.model["source"] = path.empty() ? "<built-in example>" : path;
  if (!cooling_report.is_null()) report.model["cooling"] = cooling_report;

  // Output only from here on: the config and the model were accepted.
  std::error_code ec;
  fs::create_directories(out_dir, ec);
  if (ec) throw io::ExportError("cannot create output directory " + out_dir.string() + ": " + ec.message());
  const fs::path step = out_dir / "blade.step", json = out_dir / "report.json";
  const bool ok = report.check.all_passed();
  if (ok) {
    io::write_step(step, product.shape, product.faces, {c.output.step_schema, c.output.product_name});
    timings["step"] = sw.lap();
  }
  report.timings_s = nlohmann::json(timings);
  io::write_report(json, report);
  if (!ok)
    throw ChecksFailed("solid checks failed (" + report.check.failed_names() + "); wrote " + json.string() +
                       " only, no STEP file");

  if (!quiet) {
    const auto& k = report.check;
    std::printf("%s: %s flow path, %zu sections\n", c.name.c_str(), model.trim.straight ? "straight" : "meridional",
                c.blade.sections.size());
    std::printf("  volume %.4f mm^3, surface %.4f mm^2, %d faces, bbox [%.3f %.3f %.3f] - [%.3f %.3f %.3f] mm\n",
                k.volume, k.area, k.face_count, k.bbox_min[0], k.bbox_min[1], k.bbox_min[2], k.bbox_max[0],
                k.bbox_max[1], k.bbox_max[2]);
    std::printf("  checks:");
    for (const brep::Check* x : k.checks()) std::printf(" %s %s", x->name.c_str(), x->passed ? "ok" : "FAILED");
    std::printf("\n  time:");
    double total = 0;
    for (const auto& [stage, s] : timings.items()) {
      std::printf(" %s %.3f s,", stage.c_str(), s.get<double>());
      total += s.get<double>();
    }
    std::printf(" total %.3f s\n", total);
    for (const auto& w : solid.warnings) std::printf("  warning: %s\n", w.c_str());
    std::printf("  wrote %s, %s\n", step.string().c_str(), json.string().c_str());
  }
  return kOk;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"coolinggen: verified CAD models of cooled turbine blades (units mm, degrees)", "coolinggen"};
  app.set_version_flag("--version", "coolinggen 0.1.0");
  app.require_subcommand(1);

  std::string build_config, validate_config;
  fs::path out_dir;
  bool quiet = false;
  CLI::App* build = app.add_subcommand("build", "Build the blade solid; write DIR/blade.step and DIR/report.json");
  build->add_option("config", build_config, "Config file (JSON, see data/schema/coolinggen.schema.json); "
                                            "without it the built-in example (coolinggen example) is built");
  build->add_option("-o,--output", out_dir, "Output directory (created if missing)")->required();
  build->add_flag("-q,--quiet", quiet, "Print nothing on success");
  CLI::App* validate = app.add_subcommand("validate", "Parse and check a config (builds the blade model); writes nothing");
  validate->add_option("config", validate_config, "Config file (JSON)")->required();
  CLI::App* example = app.add_subcommand("example", "Print the built-in example config (JSON) to stdout");

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    return error_exit(kUsage, std::string(e.what()) + " (see coolinggen --help)");
  }

  silence_occt();
  try {
    if (*example) {
      std::fputs(config::builtin_example_json(), stdout);
      return kOk;
    }
    if (*validate) return run_validate(validate_config);
    return run_build(build_config, out_dir, quiet);
  } catch (const config::ConfigError& e) {
    return error_exit(kBadConfig, e.what());
  } catch (const io::ExportError& e) {
    return error_exit(kOutputFailure, e.what());
  } catch (const Error& e) {  // InvalidGeometry / AlgorithmFailure from the model or solid, ChecksFailed
    return error_exit(kModelFailure, e.what());
  } catch (const Standard_Failure& e) {
    return error_exit(kUnexpected, std::string("OCCT: ") + e.GetMessageString());
  } catch (const std::exception& e) {
    return error_exit(kUnexpected, e.what());
  }
}
