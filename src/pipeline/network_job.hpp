#pragma once
// The build's stage "coolant_network" (build.hpp): the coolant flow network of the built part
// (src/network: graph, CalculiX deck, ccx, results, film-hole table) as the files and headline numbers of
// BuildResult::network, which the output format "network" writes (network_format.hpp).
#include "src/config/config.hpp"
#include "src/pipeline/build_result.hpp"

namespace cg::pipeline {

/// The network of `result`. A part the network cannot be made from gives NetworkFiles::error (the
/// format "network" then fails naming it); a missing or failing solver gives warnings.
NetworkFiles solve_network(const config::Config& config, const BuildResult& result);

}  // namespace cg::pipeline
