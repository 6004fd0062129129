#include "src/study/variant_config.hpp"

#include "export/atomic_file.hpp"
#include "src/config/config.hpp"
#include "src/pipeline/build.hpp"
#include "src/pipeline/cooling_stage_cache.hpp"
#include "src/pipeline/report.hpp"
#include "src/study/text_file.hpp"

namespace cg::study {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// Every "file" member (section point files, cooling tables) relative to the base config's directory.
void absolute_files(json& node, const fs::path& base_dir) {
  if (node.is_array())
    for (json& x : node) absolute_files(x, base_dir);
  if (!node.is_object()) return;
  for (auto it = node.begin(); it != node.end(); ++it) {
    if (it.key() == "file" && it->is_string() && fs::path(it->get<std::string>()).is_relative())
      *it = (base_dir / it->get<std::string>()).lexically_normal().string();
    else
      absolute_files(*it, base_dir);
  }
}

}  // namespace

json variant_document(const Study& s, const Variant& v) {
  json doc = s.base;
  doc.erase("$schema");  // relative to the base config, not to the variant's directory
  absolute_files(doc, fs::absolute(s.base_dir));
  for (std::size_t k = 0; k < s.parameters.size(); ++k)
    apply_field(doc, s.parameters[k].path, s.parameters[k].mode, v.values[k], s.parameters[k].field + ".path");
  doc["name"] = s.name + "_" + v.id;
  if (!doc.contains("output") || !doc["output"].is_object()) doc["output"] = json::object();
  doc["output"]["formats"] = config::output_format_names(s.outputs);
  return doc;
}

PreparedVariant prepare_variant(const Study& s, const Variant& v, const fs::path& study_dir) {
  PreparedVariant p;
  p.variant = v;
  p.dir = study_dir / "variants" / v.id;
  p.config_file = p.dir / "config.json";
  std::error_code ec;
  fs::create_directories(p.dir, ec);
  if (ec) throw io::ExportError("cannot create " + p.dir.string() + ": " + ec.message());
  try {
    const std::string text = variant_document(s, v).dump(2) + "\n";
    if (read_text(p.config_file) != text)  // an unchanged variant keeps its file (and its time stamp)
      write_text(p.config_file, text);
    const config::Config c = config::load_config_file(p.config_file);
    pipeline::validate(c);
    p.input_hash = pipeline::input_hash(c);
    if (!c.cooling.passages.empty()) p.cooling_key = pipeline::cooling_stage_key(c, pipeline::BuildOptions{}.verification);
  } catch (const io::ExportError&) {
    throw;
  } catch (const Error& e) {  // ConfigError, or the model's own refusal of the geometry
    p.refusal = e.what();
    for (char& ch : p.refusal)
      if (ch == '\n' || ch == '\r') ch = ' ';
  }
  return p;
}

}  // namespace cg::study
