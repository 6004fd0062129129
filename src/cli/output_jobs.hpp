#pragma once
// The jobs of the CLI that write files through the hand-off libraries (VTK, gmsh, CGNS and OCCT's data
// exchange): 140 of the 169 shared libraries the whole pipeline links. The coolinggen executable takes
// them from its output module, libcoolinggen_outputs.so, loaded when a command first writes files
// (output_jobs/loaded.cpp), so `validate` and every design refused before its outputs start with the
// 29 libraries the model and the plan need: the dynamic loader's symbol lookups in the other 140 were
// 0.1-0.2 s of a 0.3-0.9 s `validate` (docs/cli.md, Start-up). What links coolinggen_cli_commands without
// the executable's main (the CLI tests) links coolinggen_cli_linked_jobs (output_jobs/linked.cpp),
// which calls them directly; the module is that file built as a shared object (output_jobs/module.cpp).
#include "src/pipeline/grid_job.hpp"
#include "src/pipeline/mesh_job.hpp"
#include "src/pipeline/outputs.hpp"

namespace cg::cli {

struct OutputJobs {
  decltype(&pipeline::write_outputs) write_outputs = nullptr;  ///< build, network
  decltype(&pipeline::write_mesh) write_mesh = nullptr;        ///< mesh
  decltype(&pipeline::write_grid_outputs) write_grid_outputs = nullptr;  ///< grid
};

/// The jobs. In the executable the first call loads the output module; throws AlgorithmFailure (exit 3,
/// a CoolingGen failure) when it cannot be loaded, naming the file and the loader's reason.
const OutputJobs& output_jobs();

/// Throws output_jobs()'s AlgorithmFailure now when the module is missing (a job calls it before its
/// build, so that a broken installation fails at once, not after it; the module is loaded only to write).
void find_output_jobs();

}  // namespace cg::cli
