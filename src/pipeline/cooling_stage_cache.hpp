#pragma once
// The cooling stage of run_build through the stage cache (stage_cache.hpp): its key and its result as
// an entry.
//
// Key: SHA-256 of the cache format, the tool version, a fingerprint of the binary that holds this code
// (SHA-256 of its file: a rebuilt tool never reads the entries of another build; when the file cannot
// be read, a value of this process alone), verify_each_step,
// and what the blade model, the solid and the cooling stage read: the parsed config without the fields
// only other stages read (kNotCoolingInputs: name, description, output, mesh, grid, coolant and the film
// fields under "cooling"), then the bytes of the config's section point files and cooling table files
// (hash_inputs, as the input hash). Everything else (units, flow path, sections, blade, booleans,
// cooling.core, cooling.radial_passages, and any field added later) is in the key.
//
// Entry: the cooled blade and the wall-feature tools (turbulators, pin fins, slots) as shapes with
// their face names, and as JSON the passage report, the blade's check, and of the core what the film
// stage places holes and inserts against (features/film/film_cavity.hpp):
// the inner wall, the chambers and the end walls. A restored PassagesResult therefore holds every field
// the film stage and the report read; the core's rib tubes, chamber systems and boolean tools, the
// wall features' placement records and boolean step reports are not restored (nothing after the
// cooling stage reads them; the static_asserts in the .cpp fail when one of these types changes, so a
// new field is placed in the entry or declared unread).
#include <string>
#include <vector>

#include "features/internal_cooling.hpp"
#include "src/config/config.hpp"
#include "src/pipeline/stage_cache.hpp"

namespace cg::pipeline {

inline constexpr const char* kCoolingStage = "cooling";

/// Config fields the blade model, the solid and the cooling stage do not read (paths as in config
/// errors).
extern const std::vector<std::string> kNotCoolingInputs;

/// "sha256:..." hex key of the cooling stage of `config` (see above) when built with `verification`
/// (EachStep verifies inside the stage and has its own entries; FinalOnly and None build it alike).
std::string cooling_stage_key(const config::Config& config, features::Verification verification);

/// The entry of a cooling stage's result. Throws cg::Error when a part would not come back exactly
/// (then nothing is stored).
StageCacheEntry encode_cooling_stage(const features::PassagesResult& result);

/// The result stored in `entry`, for the blade model `model` (built from the same config parts).
/// Throws cg::Error for an entry this code cannot read.
features::PassagesResult decode_cooling_stage(const StageCacheEntry& entry, const blade::BladeModel& model);

}  // namespace cg::pipeline
