#pragma once
// The stage cache of design studies (issue 22): what a stage of run_build produced, stored under the
// hash of everything the stage read (stage_cache_key in cooling_stage_cache.hpp), so that a variant
// that differs from an earlier one only in later stages starts from the stored result instead of
// building it again.
//
// An entry is the stage's shapes (one compound in OCCT's binary B-rep format, BinTools: exact doubles)
// and the rest as JSON (face names, the stage's report, the objects later stages need). Entries live
//  - in memory (kMemory, and in front of the disk with kDisk): for one process building several
//    variants (the library, the Python module); the few most recently stored are kept;
//  - on disk (kDisk) under DIRECTORY/<stage>/<key>/ (shapes.bin, stage.json): for the variant
//    processes of `coolinggen sweep` (DIR/cache of the study). An entry is written into a temporary
//    directory beside its place and renamed there when complete (rename is atomic on POSIX), so a
//    process reading the cache sees a whole entry or none; of two processes storing the same key the
//    second one's rename fails and its copy is dropped (both hold the same result).
// The key holds the tool version and a fingerprint of the binary, so entries of another build of the
// tool are never read. An entry that cannot be read is removed and counts as absent.
#include <nlohmann/json.hpp>

#include <cstddef>
#include <filesystem>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace cg::pipeline {

enum class StageCacheMode {
  kOff,     ///< every stage is built
  kMemory,  ///< entries kept in this process only
  kDisk,    ///< entries also on disk (StageCacheOptions::directory), shared by processes
};

/// "off", "memory", "disk"; parse_stage_cache_mode throws ConfigError naming `field` for other names.
const char* stage_cache_mode_name(StageCacheMode mode);
StageCacheMode parse_stage_cache_mode(const std::string& name, const std::string& field);

struct StageCacheOptions {
  StageCacheMode mode = StageCacheMode::kDisk;
  std::filesystem::path directory;  ///< kDisk: the cache's root (created when first stored to)
  std::size_t memory_entries = 4;   ///< entries kept in memory (the oldest stored is dropped first)
};

struct StageCacheEntry {
  std::string shapes;   ///< BinTools bytes of one compound
  nlohmann::ordered_json data;  ///< the rest of the stage's result (stage-specific), in the order it was written
};

class StageCache {
 public:
  explicit StageCache(StageCacheOptions options);
  const StageCacheOptions& options() const { return options_; }

  /// The entry of `stage` under `key` (a hex digest), from memory, else from disk (then kept in
  /// memory); none when absent. Thread-safe.
  std::shared_ptr<const StageCacheEntry> find(const std::string& stage, const std::string& key);
  /// Keeps `entry` in memory and, with kDisk, writes it. Throws io::ExportError when the disk entry
  /// cannot be written (the memory entry is kept). Thread-safe.
  void store(const std::string& stage, const std::string& key, StageCacheEntry entry);

  /// Where the disk entry of `stage` and `key` is (whether or not it exists).
  std::filesystem::path entry_directory(const std::string& stage, const std::string& key) const;

 private:
  std::shared_ptr<const StageCacheEntry> read_disk(const std::string& stage, const std::string& key) const;
  void write_disk(const std::string& stage, const std::string& key, const StageCacheEntry& entry) const;
  void remember(const std::string& id, std::shared_ptr<const StageCacheEntry> entry);

  StageCacheOptions options_;
  std::mutex mutex_;
  std::vector<std::pair<std::string, std::shared_ptr<const StageCacheEntry>>> memory_;  ///< oldest first
};

}  // namespace cg::pipeline
