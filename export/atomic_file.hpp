#pragma once
// Writing output files so that a reader never sees a half-written file: the content goes to a
// temporary file in the target's directory, which is renamed over the target only when complete
// (rename within one file system is atomic on POSIX).
#include <filesystem>
#include <functional>

#include "src/core/error.hpp"

namespace cg::io {

/// An output file could not be written.
class ExportError : public Error {
 public:
  using Error::Error;
};

/// Calls write(temporary path) and renames the temporary file to `target` when write returns and
/// the file exists and is not empty. On any failure (write throws, no file, rename fails) the
/// temporary file is removed, `target` is left as it was, and the error is (re)thrown as
/// ExportError (cg::Error subclasses thrown by `write` pass unchanged).
void write_atomically(const std::filesystem::path& target, const std::function<void(const std::filesystem::path&)>& write);

}  // namespace cg::io
