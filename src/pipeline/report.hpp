#pragma once
// What report.json says about a build (export/report.hpp writes it): the tool version, the input hash,
// the model (per-section diagnostics of the built blade), the checks, the timings and the files.
#include <nlohmann/json.hpp>

#include <string>
#include <vector>

#include "export/report.hpp"
#include "src/config/config.hpp"
#include "src/pipeline/build_result.hpp"

namespace cg::pipeline {

/// The model description: name, flow path, per section (as built) the span, kind, chord and the
/// section-frame profile (chord, stagger, area, LE/TE), the blade surface's degrees and poles, the
/// options and the parsed config.
nlohmann::ordered_json report_model(const config::Config& config, const blade::BladeModel& model);

/// "sha256:<hex>" of the canonical config (the parsed document, keys sorted) and the bytes of every
/// section point file it reads, in section order, then of the cooling section's table files: equal for
/// equal inputs, whatever the formatting or the files' location.
std::string input_hash(const config::Config& config);

class Sha256;
/// What input_hash hashes, with `document` (the parsed config or a part of it, e.g. the fields one stage
/// reads: stage_cache_key.hpp) in place of the whole config: its canonical dump, then the bytes of the
/// config's section point files and cooling table files, each length-prefixed.
void hash_inputs(Sha256& hash, const nlohmann::json& document, const config::Config& config);

/// The report of `result` for the files `outputs` (report.json included) and the stage `timings`.
io::ReportContent report_content(const config::Config& config, const BuildResult& result,
                                 const std::vector<std::string>& outputs, const std::vector<StageTiming>& timings);

}  // namespace cg::pipeline
