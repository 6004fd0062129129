#pragma once
// The files of one run in one output directory, never mixed with another run's.
//
// report.json is the index of the directory: it lists the files written with it and is written last.
// Opening a directory for a run first removes the previous run's report.json, then the previous run's
// files (those that report listed, and every name an output format can write), so a model never sits
// beside a report of another run. If the run stops before commit() (error, time limit), the files it
// wrote are removed again and the directory holds no outputs at all; a directory without report.json
// is therefore never a finished run. Each file is written atomically (export/atomic_file.hpp).
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace cg::pipeline {

class OutputDirectory {
 public:
  /// Creates `dir` if missing and removes the previous run's outputs: the files listed in its
  /// `index_name` (when that was written by coolinggen) and every name in `owned_names`.
  /// Throws io::ExportError.
  OutputDirectory(std::filesystem::path dir, std::string index_name, const std::vector<std::string>& owned_names);
  ~OutputDirectory();
  OutputDirectory(const OutputDirectory&) = delete;
  OutputDirectory& operator=(const OutputDirectory&) = delete;

  const std::filesystem::path& path() const { return dir_; }
  /// Calls writer(dir / name), which must write that file atomically (every io:: writer does), and
  /// records the file. Throws io::ExportError if the writer throws or leaves no file.
  void write(const std::string& name, const std::function<void(const std::filesystem::path& target)>& writer);
  /// Files written so far, in order.
  const std::vector<std::string>& files() const { return files_; }
  /// Writes the index last: write_index(dir / index_name, files including the index). After this the
  /// files stay.
  void commit(const std::function<void(const std::filesystem::path& target, const std::vector<std::string>& files)>& write_index);

 private:
  std::filesystem::path dir_;
  std::string index_name_;
  std::vector<std::string> files_;
  bool committed_ = false;
};

/// True for a plain file name (no directory part, not "." or "..", not hidden): the only names an
/// index may make OutputDirectory remove.
bool is_plain_file_name(const std::string& name);

}  // namespace cg::pipeline
