#pragma once
// Whole-file text reads and atomic writes of the study's files.
#include <filesystem>
#include <string>

namespace cg::study {

/// The file's bytes; empty when it is missing or unreadable.
std::string read_text(const std::filesystem::path& file);
/// Writes `text` to `target` through a temporary file renamed when complete (io::write_atomically).
/// Throws io::ExportError.
void write_text(const std::filesystem::path& target, const std::string& text);

}  // namespace cg::study
