// output_jobs() as direct calls: the CLI tests' definition, and the output module's table (module.cpp).
#include "src/cli/output_jobs.hpp"

namespace cg::cli {

const OutputJobs& output_jobs() {
  static const OutputJobs jobs{&pipeline::write_outputs, &pipeline::write_mesh, &pipeline::write_grid_outputs};
  return jobs;
}

void find_output_jobs() {}

}  // namespace cg::cli
