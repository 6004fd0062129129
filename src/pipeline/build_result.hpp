#pragma once
// What a build produced (pipeline::run_build, build.hpp): the model, the part with its checks, the
// stages' records and the feature stages' reports. Plain data: the jobs after a build (outputs, report,
// mesh, grid) read it without depending on the build's algorithm.
#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

#include "features/film/film_report.hpp"
#include "features/passages/passage_report.hpp"
#include "src/blade/blade_surface.hpp"
#include "src/brep/named_shape.hpp"
#include "src/brep/verify.hpp"
#include "src/pipeline/stage_records.hpp"

namespace cg::pipeline {

/// The coolant flow network of a built part as the output format "network" writes it (docs/network.md).
struct NetworkFiles {
  std::string json, deck, results;   ///< network.json, network.inp, network_results.json
  std::string film_holes;            ///< film_holes.csv (empty without film holes)
  nlohmann::ordered_json summary;    ///< headline numbers (report.json "network")
  std::vector<std::string> warnings;  ///< solver missing or not converged (also on stderr)
  std::string error;                 ///< why no network could be made from the part (then the rest is empty)
};

struct BuildResult {
  blade::BladeModel model;
  /// The product: bodies[0] is the blade ("blade"), each body's faces named (src/brep/named_shape.hpp).
  brep::Part part;
  /// The blade solid before any cooling feature (its faces named): what the coolant domain of
  /// `coolinggen mesh` is cut from (coolant = uncooled - part bodies).
  brep::NamedShape uncooled;
  /// checks[i]: the checks of part[i].
  std::vector<brep::SolidCheck> checks;
  /// Warnings of the stages (e.g. general-fuse alerts), each prefixed with its stage.
  std::vector<std::string> warnings;
  /// Stages in run order.
  std::vector<StageTiming> timings;
  /// The stages that went through BuildOptions::stage_cache, in run order (empty without a cache).
  std::vector<StageCacheUse> stage_cache;
  /// What the cooling stage measured (design checks, passage sections, volumes); none when uncooled.
  std::optional<features::PassageReport> cooling;
  /// What the film stage measured (per hole, row, chamber, insert); none without film input.
  std::optional<features::FilmReport> film;
  /// The coolant flow network, solved by the stage "coolant_network" when the config selects the output
  /// format "network" and the valid part has cooling passages; none otherwise.
  std::optional<NetworkFiles> network;

  /// Every check of every body passed.
  bool valid() const;
  /// "blade: closed_mesh, brep_valid; insert_1: one_solid" (empty when valid).
  std::string failed_checks() const;
};

}  // namespace cg::pipeline
