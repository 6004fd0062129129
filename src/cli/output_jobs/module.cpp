// The output module's one entry point (libcoolinggen_outputs.so): the table of linked.cpp, found by name
// by loaded.cpp. It answers only an executable of its own version and table layout (a module left from
// another installation gives nothing rather than a table it would misread).
#include <cstddef>
#include <cstring>

#include "export/version.hpp"
#include "src/cli/output_jobs.hpp"

extern "C" __attribute__((visibility("default"))) const cg::cli::OutputJobs* coolinggen_output_jobs(const char* version,
                                                                                                    std::size_t table_size) {
  if (std::strcmp(version, cg::io::tool_version()) != 0 || table_size != sizeof(cg::cli::OutputJobs)) return nullptr;
  return &cg::cli::output_jobs();
}
