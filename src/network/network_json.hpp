#pragma once
// network.json (schema data/schema/network.schema.json): the network's nodes and elements with every
// geometric quantity a network solver needs, and network_results.json: the solved flows, pressures,
// per-row margins and hole Mach numbers (docs/outputs.md).
#include <nlohmann/json.hpp>

#include "src/network/ccx_solve.hpp"
#include "src/network/network_model.hpp"

namespace cg::network {

nlohmann::ordered_json network_json(const Network& net);

/// What the solution says per element, chamber, film row and hole; `status` and `message` always, the
/// numbers only when converged. Mass conservation is checked at every junction (largest relative
/// imbalance in "checks").
nlohmann::ordered_json results_json(const Network& net, const NetworkSolution& sol);

/// Headline numbers for report.json / results.csv: status, total flow, per chamber, worst backflow margin.
nlohmann::ordered_json results_summary(const nlohmann::ordered_json& results);

/// Isentropic Mach number at area `a` (mm^2) for mass flow `m` (kg/s) from totals pt (Pa), tt (K)
/// (1 when the flow exceeds the choked flow).
double isentropic_mach(double m, double a, double pt, double tt, const Gas& gas);

}  // namespace cg::network
