// output_jobs() of the coolinggen executable: the output module loaded on first use, from the
// executable's own folder (the build folder) or, installed, from <prefix>/<libdir>/coolinggen
// (COOLINGGEN_MODULE_DIR, relative to <prefix>/bin; cmake/CoolingGenTargets.cmake).
#include <dlfcn.h>

#include <cstddef>
#include <filesystem>
#include <mutex>
#include <string>

#include "export/version.hpp"
#include "src/cli/output_jobs.hpp"
#include "src/core/error.hpp"

namespace cg::cli {

namespace {
constexpr const char* kModule = "libcoolinggen_outputs.so";
constexpr const char* kEntry = "coolinggen_output_jobs";

// The module's file: in the executable's folder (the build folder), else installed.
std::filesystem::path module_file() {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path exe_dir = fs::read_symlink("/proc/self/exe", ec).parent_path();
  if (ec) throw AlgorithmFailure(std::string("cannot find the coolinggen executable's folder to load ") + kModule + ": " + ec.message());
  const fs::path here = exe_dir / kModule, installed = (exe_dir / COOLINGGEN_MODULE_DIR / kModule).lexically_normal();
  for (const fs::path& file : {here, installed})
    if (fs::exists(file, ec)) return file;
  throw AlgorithmFailure(std::string("the output module ") + kModule + " is missing (looked for " + here.string() + " and " +
                         installed.string() + ")");
}

const OutputJobs* load_module() {
  const std::filesystem::path file = module_file();
  void* module = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
  if (!module) throw AlgorithmFailure("cannot load the output module " + file.string() + ": " + dlerror());
  const auto entry = reinterpret_cast<const OutputJobs* (*)(const char*, std::size_t)>(dlsym(module, kEntry));
  if (!entry) throw AlgorithmFailure("the output module " + file.string() + " has no " + kEntry);
  const OutputJobs* jobs = entry(io::tool_version(), sizeof(OutputJobs));
  if (!jobs)
    throw AlgorithmFailure("the output module " + file.string() + " belongs to another build than this coolinggen " +
                           io::tool_version() + " (install both from one build)");
  return jobs;
}
}  // namespace

const OutputJobs& output_jobs() {
  static std::mutex mutex;
  static const OutputJobs* jobs = nullptr;
  const std::lock_guard<std::mutex> lock(mutex);
  if (!jobs) jobs = load_module();
  return *jobs;
}

void find_output_jobs() { module_file(); }

}  // namespace cg::cli
