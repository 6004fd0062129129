#include "src/pipeline/network_format.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <mutex>

#include "export/atomic_file.hpp"
#include "src/config/json_fields.hpp"
#include "src/network/network_stage.hpp"

namespace cg::pipeline {
namespace fs = std::filesystem;
namespace {

// The headline of the last network written, for the report of the same build result.
struct LastNetwork {
  std::mutex mutex;
  const BuildResult* owner = nullptr;
  Handle(TopoDS_TShape) shape;
  nlohmann::ordered_json summary;
  std::vector<std::string> warnings;
};

LastNetwork& last() {
  static LastNetwork l;
  return l;
}

void write_text(OutputDirectory& d, const std::string& name, const std::string& text) {
  d.write(name, [&](const fs::path& t) {
    std::ofstream out(t);
    out << text;
    if (!out) throw io::ExportError("cannot write " + t.string());
  });
}

void write_network(OutputDirectory& d, const config::Config& c, const BuildResult& r, ProgressSink*) {
  if (!r.cooling) throw io::ExportError("network: the blade has no internal cooling passages (no \"cooling\" section)");
  network::NetworkInput in;
  in.config = &c;
  in.model = &r.model;
  in.part = &r.part;
  in.passages = &*r.cooling;
  in.film = r.film ? &*r.film : nullptr;
  network::NetworkRun run;
  try {
    run = network::run_network(in);
  } catch (const network::NetworkError& e) {
    throw io::ExportError(std::string("network: ") + e.what());
  }
  write_text(d, "network.json", run.json.dump(2) + "\n");
  write_text(d, "network.inp", run.deck);
  write_text(d, "network_results.json", run.results.dump(2) + "\n");
  if (!run.film_holes.empty()) write_text(d, "film_holes.csv", run.film_holes);
  for (const std::string& w : run.warnings) std::fprintf(stderr, "warning: %s\n", w.c_str());
  LastNetwork& l = last();
  std::lock_guard<std::mutex> lock(l.mutex);
  l.owner = &r;
  l.shape = r.part.empty() ? Handle(TopoDS_TShape)() : r.part.front().geometry.shape.TShape();
  l.summary = run.summary;
  l.warnings = run.warnings;
}

}  // namespace

OutputWriter network_writer() {
  return {config::OutputFormat::Network,
          "coolant flow network solved by CalculiX (network.json, network.inp, network_results.json) and film_holes.csv",
          {"network.json", "network.inp", "network_results.json", "film_holes.csv"},
          write_network};
}

void add_network_report(const BuildResult& r, io::ReportContent& report) {
  LastNetwork& l = last();
  std::lock_guard<std::mutex> lock(l.mutex);
  if (l.owner != &r || r.part.empty() || l.shape != r.part.front().geometry.shape.TShape()) return;
  report.extra["network"] = l.summary;
  for (const std::string& w : l.warnings)
    if (std::find(report.warnings.begin(), report.warnings.end(), w) == report.warnings.end()) report.warnings.push_back(w);
}

}  // namespace cg::pipeline
