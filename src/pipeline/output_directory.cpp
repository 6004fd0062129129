#include "src/pipeline/output_directory.hpp"

#include <nlohmann/json.hpp>

#include <fstream>
#include <set>
#include <sstream>
#include <system_error>

#include "export/atomic_file.hpp"

namespace cg::pipeline {
namespace fs = std::filesystem;
namespace {

// Names listed under "outputs" in a previous index written by coolinggen (empty if none or unreadable).
std::vector<std::string> previous_outputs(const fs::path& index) {
  std::ifstream in(index, std::ios::binary);
  if (!in) return {};
  std::stringstream text;
  text << in.rdbuf();
  const nlohmann::json j = nlohmann::json::parse(text.str(), nullptr, /*allow_exceptions=*/false);
  std::vector<std::string> names;
  if (!j.is_object() || j.value("generator", "") != "coolinggen" || !j.contains("outputs") || !j["outputs"].is_array())
    return names;
  for (const auto& e : j["outputs"])
    if (e.is_string()) names.push_back(e.get<std::string>());
  return names;
}

void remove_file(const fs::path& p) {
  std::error_code ec;
  if (!fs::is_regular_file(fs::symlink_status(p, ec))) return;  // never a directory or a symlink's target
  fs::remove(p, ec);
  if (ec) throw io::ExportError("cannot remove " + p.string() + " of an earlier run: " + ec.message());
}

}  // namespace

bool is_plain_file_name(const std::string& name) {
  return !name.empty() && name[0] != '.' && name.find('/') == std::string::npos && name.find('\\') == std::string::npos;
}

OutputDirectory::OutputDirectory(fs::path dir, std::string index_name, const std::vector<std::string>& owned_names)
    : dir_(std::move(dir)), index_name_(std::move(index_name)) {
  std::error_code ec;
  if (fs::exists(dir_, ec) && !fs::is_directory(dir_, ec))
    throw io::ExportError("output directory " + dir_.string() + " exists and is not a directory");
  fs::create_directories(dir_, ec);
  if (ec) throw io::ExportError("cannot create output directory " + dir_.string() + ": " + ec.message());
  // The index first: from here on no report claims the files that are about to change.
  std::set<std::string> stale(owned_names.begin(), owned_names.end());
  for (const std::string& n : previous_outputs(dir_ / index_name_))
    if (is_plain_file_name(n)) stale.insert(n);
  remove_file(dir_ / index_name_);
  for (const std::string& n : stale) remove_file(dir_ / n);
}

OutputDirectory::~OutputDirectory() {
  if (committed_) return;
  std::error_code ec;
  for (const std::string& n : files_) fs::remove(dir_ / n, ec);
}

void OutputDirectory::write(const std::string& name, const std::function<void(const fs::path&)>& writer) {
  if (!is_plain_file_name(name)) throw io::ExportError("invalid output file name '" + name + "'");
  const fs::path target = dir_ / name;
  writer(target);
  std::error_code ec;
  if (!fs::is_regular_file(target, ec)) throw io::ExportError("writing " + target.string() + " produced no file");
  files_.push_back(name);
}

void OutputDirectory::commit(const std::function<void(const fs::path&, const std::vector<std::string>&)>& write_index) {
  std::vector<std::string> all = files_;
  all.push_back(index_name_);
  write_index(dir_ / index_name_, all);
  files_ = all;
  committed_ = true;
}

}  // namespace cg::pipeline
