#include "src/pipeline/stage_cache.hpp"

#include <unistd.h>

#include <atomic>
#include <fstream>
#include <sstream>
#include <system_error>

#include "export/atomic_file.hpp"
#include "src/config/config_error.hpp"

namespace cg::pipeline {
namespace {

namespace fs = std::filesystem;

constexpr const char* kShapesFile = "shapes.bin";
constexpr const char* kDataFile = "stage.json";

std::optional<std::string> read_bytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return std::nullopt;
  std::ostringstream bytes;
  bytes << in.rdbuf();
  if (!in.good() && !in.eof()) return std::nullopt;
  return bytes.str();
}

void write_bytes(const fs::path& file, const std::string& bytes) {
  std::ofstream out(file, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  out.close();
  if (!out) throw io::ExportError("stage cache: cannot write " + file.string());
}

// A unique name beside `target` (same directory, so the rename stays on one file system).
fs::path temporary_beside(const fs::path& target) {
  static std::atomic<unsigned> counter{0};
  return target.parent_path() / ("." + target.filename().string() + ".tmp." + std::to_string(::getpid()) + "." +
                                 std::to_string(counter++));
}

}  // namespace

const char* stage_cache_mode_name(StageCacheMode mode) {
  switch (mode) {
    case StageCacheMode::kOff: return "off";
    case StageCacheMode::kMemory: return "memory";
    case StageCacheMode::kDisk: return "disk";
  }
  return "off";
}

StageCacheMode parse_stage_cache_mode(const std::string& name, const std::string& field) {
  for (StageCacheMode m : {StageCacheMode::kOff, StageCacheMode::kMemory, StageCacheMode::kDisk})
    if (name == stage_cache_mode_name(m)) return m;
  throw config::ConfigError(field + ": unknown stage cache mode \"" + name + "\" (allowed: \"off\", \"memory\", \"disk\")");
}

StageCache::StageCache(StageCacheOptions options) : options_(std::move(options)) {
  if (options_.mode == StageCacheMode::kDisk && options_.directory.empty())
    throw config::ConfigError("stage cache: the disk mode needs a directory");
}

fs::path StageCache::entry_directory(const std::string& stage, const std::string& key) const {
  return options_.directory / stage / key;
}

std::shared_ptr<const StageCacheEntry> StageCache::find(const std::string& stage, const std::string& key) {
  if (options_.mode == StageCacheMode::kOff) return nullptr;
  const std::string id = stage + "/" + key;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    for (const auto& [k, e] : memory_)
      if (k == id) return e;
  }
  if (options_.mode != StageCacheMode::kDisk) return nullptr;
  std::shared_ptr<const StageCacheEntry> e = read_disk(stage, key);
  if (e) remember(id, e);
  return e;
}

void StageCache::store(const std::string& stage, const std::string& key, StageCacheEntry entry) {
  if (options_.mode == StageCacheMode::kOff) return;
  auto e = std::make_shared<const StageCacheEntry>(std::move(entry));
  remember(stage + "/" + key, e);
  if (options_.mode == StageCacheMode::kDisk) write_disk(stage, key, *e);
}

void StageCache::remember(const std::string& id, std::shared_ptr<const StageCacheEntry> entry) {
  std::lock_guard<std::mutex> lock(mutex_);
  for (auto it = memory_.begin(); it != memory_.end(); ++it)
    if (it->first == id) {
      memory_.erase(it);
      break;
    }
  memory_.emplace_back(id, std::move(entry));
  while (memory_.size() > std::max<std::size_t>(options_.memory_entries, 1)) memory_.erase(memory_.begin());
}

std::shared_ptr<const StageCacheEntry> StageCache::read_disk(const std::string& stage, const std::string& key) const {
  const fs::path dir = entry_directory(stage, key);
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) return nullptr;
  const std::optional<std::string> shapes = read_bytes(dir / kShapesFile), data = read_bytes(dir / kDataFile);
  auto e = std::make_shared<StageCacheEntry>();
  if (shapes && data) {
    e->shapes = *shapes;
    e->data = nlohmann::ordered_json::parse(*data, nullptr, /*allow_exceptions=*/false);
  }
  if (!shapes || !data || !e->data.is_object() || e->data.value("key", "") != key || e->shapes.empty()) {
    // Not an entry this code wrote whole (entries appear by rename): set it aside and rebuild.
    const fs::path aside = temporary_beside(dir);
    fs::rename(dir, aside, ec);
    if (!ec) fs::remove_all(aside, ec);
    return nullptr;
  }
  return e;
}

void StageCache::write_disk(const std::string& stage, const std::string& key, const StageCacheEntry& entry) const {
  const fs::path dir = entry_directory(stage, key);
  std::error_code ec;
  fs::create_directories(dir.parent_path(), ec);
  if (ec) throw io::ExportError("stage cache: cannot create " + dir.parent_path().string() + ": " + ec.message());
  if (fs::is_directory(dir, ec)) return;  // another process stored it
  const fs::path tmp = temporary_beside(dir);
  try {
    fs::create_directory(tmp);
    write_bytes(tmp / kShapesFile, entry.shapes);
    nlohmann::ordered_json data = entry.data;
    data["key"] = key;
    write_bytes(tmp / kDataFile, data.dump());
  } catch (const std::exception& e) {
    fs::remove_all(tmp, ec);
    throw io::ExportError(std::string("stage cache: cannot write an entry in ") + dir.parent_path().string() + ": " + e.what());
  }
  fs::rename(tmp, dir, ec);
  if (ec) {
    fs::remove_all(tmp, ec);  // the same key stored meanwhile by another process (or no permission): drop ours
    if (!fs::is_directory(dir, ec)) throw io::ExportError("stage cache: cannot store " + dir.string());
  }
}

}  // namespace cg::pipeline
