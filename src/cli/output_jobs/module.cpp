// The output module's one entry point (libcoolinggen_outputs.so): the table of linked.cpp, found by name
// by loaded.cpp. The module is built from the same sources as the executable, by the same compiler,
// so the table's types agree on both sides.
#include "src/cli/output_jobs.hpp"

extern "C" __attribute__((visibility("default"))) const cg::cli::OutputJobs* coolinggen_output_jobs() {
  return &cg::cli::output_jobs();
}
