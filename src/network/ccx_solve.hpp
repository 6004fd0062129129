#pragma once
// Runs CalculiX (`ccx`, Debian calculix-ccx) on a network deck under a time limit and reads its results
// (NAME.dat: PN, NT at the corner nodes, MF at the mid nodes). Converged only when ccx exits 0, prints
// "convergence in gas iteration" and the .dat holds every node.
#include <filesystem>
#include <string>
#include <vector>

#include "src/network/network_model.hpp"

namespace cg::network {

enum class SolveStatus {
  Converged,
  NotConverged,  ///< ccx ran but did not report convergence (or its results are incomplete)
  TimedOut,      ///< killed at the time limit
  NoSolver,      ///< no `ccx` on PATH
};
const char* name(SolveStatus s);  ///< "converged", "not_converged", "timed_out", "no_solver"

struct SolveOptions {
  double time_limit_s = 60;
  std::filesystem::path work_dir;  ///< where the deck is copied and ccx runs (required)
};

struct NetworkSolution {
  SolveStatus status = SolveStatus::NotConverged;
  std::string message;  ///< one line: why not converged, or "convergence in gas iteration 12"
  int iterations = 0;
  double seconds = 0;   ///< wall clock of ccx
  std::vector<double> pressure, temperature;  ///< per node (Pa, K), index id - 1
  std::vector<double> mass_flow;              ///< per element (kg/s), index id - 1
};

/// The ccx executable on PATH (empty when none).
std::filesystem::path find_ccx();

/// Writes `deck` as work_dir/network.inp, runs ccx there and reads the results.
NetworkSolution solve_network(const Network& net, const std::string& deck, const SolveOptions& options);

}  // namespace cg::network
