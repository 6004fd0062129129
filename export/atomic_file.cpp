#include "export/atomic_file.hpp"

#include <unistd.h>

#include <atomic>
#include <string>
#include <system_error>

namespace cg::io {

void write_atomically(const std::filesystem::path& target, const std::function<void(const std::filesystem::path&)>& write) {
  namespace fs = std::filesystem;
  static std::atomic<unsigned> counter{0};
  const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw ExportError("output directory " + dir.string() + " does not exist");
  // Hidden name, unique per process and call, in the same directory (same file system as the target).
  const fs::path tmp = dir / ("." + target.filename().string() + ".tmp." + std::to_string(::getpid()) + "." +
                              std::to_string(counter++));
  try {
    write(tmp);
    if (!fs::exists(tmp, ec) || fs::file_size(tmp, ec) == 0 || ec)
      throw ExportError("writing " + target.string() + " produced no data");
    fs::rename(tmp, target, ec);
    if (ec) throw ExportError("cannot rename " + tmp.string() + " to " + target.string() + ": " + ec.message());
  } catch (const Error&) {
    fs::remove(tmp, ec);
    throw;
  } catch (const std::exception& e) {
    fs::remove(tmp, ec);
    throw ExportError("writing " + target.string() + " failed: " + e.what());
  } catch (...) {  // e.g. Standard_Failure, which is no std::exception
    fs::remove(tmp, ec);
    throw ExportError("writing " + target.string() + " failed");
  }
}

}  // namespace cg::io
