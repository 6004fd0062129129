#pragma once
// The network stage as one call (facade of this folder): graph from the built part, deck, solve,
// results and the film-hole table. The pipeline's output format "network" and `coolinggen network`
// write what it returns (network.json, network.inp, network_results.json, film_holes.csv).
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "src/network/ccx_solve.hpp"
#include "src/network/network_graph.hpp"

namespace cg::network {

struct NetworkRun {
  Network network;
  NetworkSolution solution;
  std::string deck;                ///< network.inp
  nlohmann::ordered_json json;     ///< network.json
  nlohmann::ordered_json results;  ///< network_results.json
  nlohmann::ordered_json summary;  ///< headline numbers (report.json "network")
  std::string film_holes;          ///< film_holes.csv (empty without film holes)
  std::vector<std::string> warnings;  ///< not converged, no solver (also in summary)
  double seconds = 0;              ///< the whole stage, wall clock
};

/// Builds, writes (in memory) and solves the network of `in`. Throws NetworkError when the part has no
/// network; a solver that is missing or does not converge is a warning, never an exception.
NetworkRun run_network(const NetworkInput& in);

}  // namespace cg::network
