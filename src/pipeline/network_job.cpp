#include "src/pipeline/network_job.hpp"

#include "src/network/network_stage.hpp"

namespace cg::pipeline {

NetworkFiles solve_network(const config::Config& c, const BuildResult& r) {
  network::NetworkInput in;
  in.config = &c;
  in.model = &r.model;
  in.part = &r.part;
  in.passages = r.cooling ? &*r.cooling : nullptr;
  in.film = r.film ? &*r.film : nullptr;
  NetworkFiles f;
  try {
    const network::NetworkRun run = network::run_network(in);
    f.json = run.json.dump(2) + "\n";
    f.deck = run.deck;
    f.results = run.results.dump(2) + "\n";
    f.film_holes = run.film_holes;
    f.summary = run.summary;
    f.warnings = run.warnings;
  } catch (const network::NetworkError& e) {
    f.error = e.what();
  }
  return f;
}

}  // namespace cg::pipeline
