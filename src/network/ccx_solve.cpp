#include "src/network/ccx_solve.hpp"

#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "src/core/process_pool.hpp"
#include "src/network/ccx_deck.hpp"

namespace cg::network {
namespace fs = std::filesystem;
namespace {

std::string read_text(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// The "id value" lines of each block of the .dat whose header contains `title`, into out[id].
void read_block(const std::string& dat, const std::string& title, std::vector<double>& out, int first_id, double scale) {
  std::istringstream in(dat);
  std::string line;
  bool inside = false;
  while (std::getline(in, line)) {
    if (line.find(title) != std::string::npos) {
      inside = true;
      continue;
    }
    if (!inside) continue;
    std::istringstream ls(line);
    int id = 0;
    double v = 0;
    if (!(ls >> id >> v)) {
      if (line.find_first_not_of(" \t\r") != std::string::npos) inside = false;  // the next block's header
      continue;
    }
    const int k = id - first_id;
    if (k >= 0 && k < static_cast<int>(out.size())) out[static_cast<std::size_t>(k)] = v * scale;
  }
}

bool all_set(const std::vector<double>& v) {
  for (double x : v)
    if (std::isnan(x)) return false;
  return true;
}

}  // namespace

const char* name(SolveStatus s) {
  switch (s) {
    case SolveStatus::Converged: return "converged";
    case SolveStatus::NotConverged: return "not_converged";
    case SolveStatus::TimedOut: return "timed_out";
    case SolveStatus::NoSolver: return "no_solver";
  }
  return "";
}

fs::path find_ccx() {
  const char* path = std::getenv("PATH");
  std::istringstream dirs(path ? path : "");
  std::string d;
  while (std::getline(dirs, d, ':')) {
    const fs::path p = fs::path(d.empty() ? "." : d) / "ccx";
    std::error_code ec;
    if (fs::is_regular_file(p, ec) && access(p.c_str(), X_OK) == 0) return p;
  }
  return {};
}

NetworkSolution solve_network(const Network& net, const std::string& deck, const SolveOptions& options) {
  NetworkSolution sol;
  const fs::path ccx = find_ccx();
  if (ccx.empty()) {
    sol.status = SolveStatus::NoSolver;
    sol.message = "no CalculiX solver: `ccx` is not on PATH (Debian package calculix-ccx)";
    return sol;
  }
  fs::create_directories(options.work_dir);
  const fs::path job = options.work_dir / "network";
  {
    std::ofstream out(job.string() + ".inp");
    out << deck;
  }
  study::ProcessSpec spec;
  spec.argv = {ccx.string(), "-i", job.string()};
  spec.stdout_file = options.work_dir / "ccx.out";
  spec.stderr_file = options.work_dir / "ccx.err";
  spec.kill_after_s = options.time_limit_s;
  const study::ProcessResult run = study::run_processes({spec}, {}).front();
  sol.seconds = run.seconds;
  const std::string log = read_text(spec.stdout_file);
  if (run.killed_for_time) {
    sol.status = SolveStatus::TimedOut;
    sol.message = "ccx did not finish within coolant.time_limit_s = " + std::to_string(options.time_limit_s) + " s";
    return sol;
  }
  const std::string marker = "convergence in gas iteration";
  const std::size_t at = log.rfind(marker);
  if (at != std::string::npos) sol.iterations = std::atoi(log.c_str() + at + marker.size());
  const std::size_t nn = net.nodes.size(), ne = net.elements.size();
  sol.pressure.assign(nn, kUnset);
  sol.temperature.assign(nn, kUnset);
  sol.mass_flow.assign(ne, kUnset);
  const std::string dat = read_text(job.string() + ".dat");
  read_block(dat, "network pressures", sol.pressure, 1, 1e6);
  read_block(dat, "temperatures for set NCORNER", sol.temperature, 1, 1);
  read_block(dat, "mass flows for set NMID", sol.mass_flow, static_cast<int>(nn) + 1, 1e3);
  // The shared sink nodes carry no element in the deck (each exit has its own copy): their values are
  // the boundary conditions.
  for (const Node& n : net.nodes)
    if (n.kind == NodeKind::Sink) {
      const std::size_t k = static_cast<std::size_t>(n.id - 1);
      if (std::isnan(sol.pressure[k]) || sol.pressure[k] == 0) sol.pressure[k] = n.pressure;
      if (std::isnan(sol.temperature[k]) || sol.temperature[k] == 0) sol.temperature[k] = n.temperature;
    }
  if (run.exit_code != 0 || at == std::string::npos || !all_set(sol.pressure) || !all_set(sol.mass_flow)) {
    sol.status = SolveStatus::NotConverged;
    std::string err;
    const std::size_t e = log.find("*ERROR");
    if (e != std::string::npos) err = log.substr(e, log.find('\n', log.find('\n', e) + 1) - e);
    for (char& ch : err)
      if (ch == '\n') ch = ' ';
    sol.message = "ccx did not converge (exit " + std::to_string(run.exit_code) + (err.empty() ? "" : ": " + err) + ")";
    return sol;
  }
  sol.status = SolveStatus::Converged;
  sol.message = marker + " " + std::to_string(sol.iterations);
  return sol;
}

}  // namespace cg::network
