#include "src/pipeline/network_format.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>

#include "export/atomic_file.hpp"
#include "src/config/json_fields.hpp"

namespace cg::pipeline {
namespace fs = std::filesystem;
namespace {

void write_text(OutputDirectory& d, const std::string& name, const std::string& text) {
  d.write(name, [&](const fs::path& t) {
    std::ofstream out(t);
    out << text;
    if (!out) throw io::ExportError("cannot write " + t.string());
  });
}

void write_network(OutputDirectory& d, const config::Config&, const BuildResult& r, ProgressSink*) {
  if (!r.cooling) throw io::ExportError("network: the blade has no internal cooling passages (no \"cooling\" section)");
  if (!r.network) throw io::ExportError("network: this build did not solve the coolant network (its config did not select the format)");
  if (!r.network->error.empty()) throw io::ExportError("network: " + r.network->error);
  write_text(d, "network.json", r.network->json);
  write_text(d, "network.inp", r.network->deck);
  write_text(d, "network_results.json", r.network->results);
  if (!r.network->film_holes.empty()) write_text(d, "film_holes.csv", r.network->film_holes);
  for (const std::string& w : r.network->warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
}

}  // namespace

OutputWriter network_writer() {
  return {config::OutputFormat::Network,
          "coolant flow network solved by CalculiX (network.json, network.inp, network_results.json) and film_holes.csv",
          {"network.json", "network.inp", "network_results.json", "film_holes.csv"},
          write_network};
}

void add_network_report(const BuildResult& r, io::ReportContent& report) {
  if (!r.network || !r.network->error.empty()) return;
  report.extra["network"] = r.network->summary;
  for (const std::string& w : r.network->warnings)
    if (std::find(report.warnings.begin(), report.warnings.end(), w) == report.warnings.end()) report.warnings.push_back(w);
}

}  // namespace cg::pipeline
