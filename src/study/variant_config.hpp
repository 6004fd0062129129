#pragma once
// One variant's config: the base config with the variant's parameter values applied, its name
// "<study>_<id>", its output formats the study's "outputs" (report.json only by default) and the base
// config's relative file paths made absolute (the variant's config.json lives elsewhere). Written to
// DIR/variants/<id>/config.json and checked there, as the build of that file will read it: parsing
// and what `coolinggen validate` runs (pipeline::validate). A refused variant never gets a process.
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

#include "src/study/design.hpp"
#include "src/study/study_file.hpp"

namespace cg::study {

struct PreparedVariant {
  Variant variant;
  std::filesystem::path dir;          ///< DIR/variants/<id>
  std::filesystem::path config_file;  ///< dir/config.json
  std::string input_hash;             ///< as report.json will carry it (pipeline::input_hash); empty when refused
  std::string refusal;                ///< the config error (one line, starts with the field); empty: valid
  /// The key of its cooling stage in the stage cache (pipeline::cooling_stage_key); empty when refused
  /// or uncooled. Variants with equal keys share the stage.
  std::string cooling_key;
  bool refused() const { return !refusal.empty(); }
};

/// The variant's config document.
nlohmann::json variant_document(const Study& study, const Variant& variant);

/// Writes the variant's config.json under `study_dir`/variants/<id>/ and checks it. Throws
/// io::ExportError when the file cannot be written; config errors make the variant refused.
PreparedVariant prepare_variant(const Study& study, const Variant& variant, const std::filesystem::path& study_dir);

}  // namespace cg::study
