#include "src/config/coolant_config.hpp"

#include <cmath>
#include <limits>

#include "src/core/format.hpp"

namespace cg::config {
namespace {

constexpr const char* kSinkFields[] = {"suction_side_pa", "pressure_side_pa", "showerhead_pa", "trailing_edge_pa", "tip_pa"};
// Pressures from 1 kPa to 100 MPa, temperatures 200-2000 K: beyond these the gas model of the network
// (ideal gas, constant cp) is not meant to be used.
const Range kPressure = closed(1e3, 1e8);

}  // namespace

const char* CoolantConfig::sink_field(SinkKind kind) { return kSinkFields[static_cast<int>(kind)]; }

double CoolantConfig::sink(SinkKind kind) const {
  const double p = sink_by_kind[static_cast<std::size_t>(kind)];
  return std::isnan(p) ? sink_static_pressure : p;
}

double CoolantConfig::sink(const std::string& row, SinkKind kind) const {
  const auto it = sink_by_row.find(row);
  return it != sink_by_row.end() ? it->second : sink(kind);
}

CoolantConfig parse_coolant(const Field& f) {
  f.expect_object({"supply", "sinks", "gas", "rotational_speed_rpm", "time_limit_s"});
  CoolantConfig c;
  const Field supply = f.at("supply");
  supply.expect_object({"total_pressure_pa", "total_temperature_k"});
  c.supply_total_pressure = supply.at("total_pressure_pa").number(kPressure, "Pa");
  c.supply_total_temperature = supply.at("total_temperature_k").number(closed(200, 2000), "K");
  const Field sinks = f.at("sinks");
  sinks.expect_object({"static_pressure_pa", "suction_side_pa", "pressure_side_pa", "showerhead_pa", "trailing_edge_pa", "tip_pa", "rows"});
  // Every sink below the supply: otherwise the exit would feed the blade.
  const Range below = {1e3, c.supply_total_pressure, false, true};
  c.sink_static_pressure = sinks.at("static_pressure_pa").number(below, "Pa");
  for (int k = 0; k < 5; ++k)
    c.sink_by_kind[static_cast<std::size_t>(k)] = sinks.has(kSinkFields[k]) ? sinks.at(kSinkFields[k]).number(below, "Pa")
                                                   : std::numeric_limits<double>::quiet_NaN();
  if (sinks.has("rows")) {
    // Row names are checked against the cooling section where both are known (config.cpp).
    const Field rows = sinks.at("rows");
    if (!rows.is_object()) fail(rows.path(), "must be an object of exit rows and their static pressures (Pa)");
    for (const auto& item : rows.json().items()) c.sink_by_row[item.key()] = rows.at(item.key().c_str()).number(below, "Pa");
  }
  if (f.has("gas")) {
    const Field gas = f.at("gas");
    gas.expect_object({"gas_constant_j_kg_k", "cp_j_kg_k", "viscosity_pa_s"});
    c.gas_constant = gas.number_or("gas_constant_j_kg_k", c.gas_constant, closed(50, 5000), "J/(kg K)");
    c.cp = gas.number_or("cp_j_kg_k", 0, {0, 20000, true, false}, "J/(kg K)");
    if (gas.has("cp_j_kg_k") && !(c.cp > c.gas_constant))
      fail(gas.at("cp_j_kg_k").path(), "must be > gas_constant_j_kg_k = " + format_number(c.gas_constant) +
                                           " J/(kg K) (cp > R), got " + format_number(c.cp));
    c.viscosity = gas.number_or("viscosity_pa_s", 0, {0, 1e-2, true, false}, "Pa s");
  }
  c.rotational_speed_rpm = f.number_or("rotational_speed_rpm", 0, closed(0, 100000), "rpm");
  c.time_limit_s = f.number_or("time_limit_s", 60, closed(1, 3600), "s");
  return c;
}

}  // namespace cg::config
