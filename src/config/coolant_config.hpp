#pragma once
// The "coolant" section of the configuration (data/schema/coolinggen.schema.json): the boundary
// conditions of the coolant flow network (src/network, docs/network.md). Not a geometry input: it is
// not part of the cooling stage's cache key (src/pipeline/cooling_stage_cache.hpp).
//
//   "coolant": {
//     "supply": {"total_pressure_pa": 2.5e6, "total_temperature_k": 850},
//     "sinks": {"static_pressure_pa": 1.6e6,             every exit without its own value below
//               "suction_side_pa": ..., "pressure_side_pa": ..., "showerhead_pa": ..., "trailing_edge_pa": ...,
//               "tip_pa": ...,
//               "rows": {"film_row_2": ..., "showerhead_1": ..., "te_slots": ...}},   per row, over its kind
//     "gas": {"gas_constant_j_kg_k": 287.05, "cp_j_kg_k": ..., "viscosity_pa_s": ...},   default air
//     "rotational_speed_rpm": 0,       rotors: the blade's speed about the x axis
//     "time_limit_s": 60               the network solver's time limit
//   }
#include <array>
#include <limits>
#include <map>
#include <string>

#include "src/config/json_fields.hpp"

namespace cg::config {

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// Which exits a sink pressure applies to.
enum class SinkKind { SuctionSide, PressureSide, Showerhead, TrailingEdge, Tip };

struct CoolantConfig {
  double supply_total_pressure = 0;     ///< Pa
  double supply_total_temperature = 0;  ///< K
  double sink_static_pressure = 0;      ///< Pa, every exit without its own value
  /// Pa per kind (NaN: sink_static_pressure), indexed by SinkKind.
  std::array<double, 5> sink_by_kind{kNaN, kNaN, kNaN, kNaN, kNaN};
  /// Pa per exit row ("film_row_<k>", "showerhead_<k>", "te_slots"), over its kind's value.
  std::map<std::string, double> sink_by_row;
  double gas_constant = 287.05;  ///< J/(kg K)
  double cp = 0;                 ///< J/(kg K); 0: air at the supply temperature (docs/network.md)
  double viscosity = 0;          ///< Pa s; 0: air at the supply temperature (Sutherland)
  double rotational_speed_rpm = 0;
  double time_limit_s = 60;
  /// The static pressure of the sink of `kind`, Pa.
  double sink(SinkKind kind) const;
  /// The static pressure at the exits of `row` (its own value, else its kind's), Pa.
  double sink(const std::string& row, SinkKind kind) const;
  /// The field name of a kind's sink ("suction_side_pa").
  static const char* sink_field(SinkKind kind);
};

/// Parses the "coolant" object at `f`. Throws ConfigError naming the field and its range.
CoolantConfig parse_coolant(const Field& f);

}  // namespace cg::config
