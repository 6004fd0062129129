#include "src/network/network_stage.hpp"

#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <filesystem>

#include "src/network/ccx_deck.hpp"
#include "src/network/film_holes_csv.hpp"
#include "src/network/network_correlations.hpp"
#include "src/network/network_json.hpp"

namespace cg::network {
namespace fs = std::filesystem;
namespace {

// Moves every pin bank's loss to the Reynolds number of its solved flow; true when a loss changed by
// more than 1e-3 (then the deck is solved again).
bool update_pin_losses(Network& net, const NetworkSolution& sol) {
  bool changed = false;
  for (Element& e : net.elements) {
    if (!e.pins) continue;
    PinBank& b = *e.pins;
    const double m = std::abs(sol.mass_flow[static_cast<std::size_t>(e.id - 1)]);
    b.re_d = m / (e.area_in * 1e-6) * b.diameter * 1e-3 / net.gas.viscosity;
    const double k = pin_row_loss(b.re_d);
    changed = changed || std::abs(k - b.loss_per_row) > 1e-3 * b.loss_per_row;
    b.loss_per_row = k;
  }
  return changed;
}

}  // namespace

NetworkRun run_network(const NetworkInput& in) {
  const auto t0 = std::chrono::steady_clock::now();
  NetworkRun r;
  r.network = build_network(in);
  r.deck = ccx_deck(r.network);
  static std::atomic<int> counter{0};
  SolveOptions so;
  so.time_limit_s = in.config->coolant->time_limit_s;
  so.work_dir = fs::temp_directory_path() /
                ("coolinggen-network-" + std::to_string(getpid()) + "-" + std::to_string(counter.fetch_add(1)));
  r.solution = solve_network(r.network, r.deck, so);
  // Pin banks: the correlation at the solved flow (a few passes; Metzger's K varies as Re_D^-0.132).
  for (int pass = 0; pass < 5 && r.solution.status == SolveStatus::Converged && update_pin_losses(r.network, r.solution); ++pass) {
    r.deck = ccx_deck(r.network);
    r.solution = solve_network(r.network, r.deck, so);
  }
  r.json = network_json(r.network);
  std::error_code ec;
  fs::remove_all(so.work_dir, ec);
  r.results = results_json(r.network, r.solution);
  r.summary = results_summary(r.results);
  if (r.solution.status != SolveStatus::Converged) r.warnings.push_back("network: " + r.solution.message);
  const std::vector<features::SlotInfo> no_slots;
  const std::vector<features::SlotInfo>& slots = in.slots ? *in.slots : no_slots;
  if ((in.film && !in.film->holes.empty()) || !slots.empty())
    r.film_holes = film_holes_csv(in.film ? *in.film : features::FilmReport(), slots, &r.network, &r.solution);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.summary["seconds"] = r.seconds;
  return r;
}

}  // namespace cg::network
