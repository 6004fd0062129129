#include "src/study/study_file.hpp"

#include <cmath>
#include <fstream>

#include "src/config/config.hpp"
#include "src/config/json_document.hpp"
#include "src/config/json_fields.hpp"
#include "src/core/format.hpp"
#include "src/study/text_file.hpp"

namespace cg::study {
namespace {

namespace fs = std::filesystem;
using config::Field;
using nlohmann::json;

std::string read_file(const fs::path& file, const std::string& field) {
  std::error_code ec;
  if (!fs::exists(file, ec)) config::fail(field, file.string() + " does not exist");
  if (fs::is_directory(file, ec)) config::fail(field, file.string() + " is a directory, not a file");
  std::ifstream probe(file);
  if (!probe) config::fail(field, "cannot read " + file.string());
  return read_text(file);
}

Parameter parameter(const Field& f) {
  f.expect_object({"name", "path", "mode", "values", "range", "levels", "integer"});
  Parameter p;
  p.field = f.path();
  p.path = parse_field_path(f.at("path").string(), f.at("path").path());
  p.name = f.has("name") ? f.at("name").string() : p.path.text;
  if (f.has("mode")) p.mode = f.at("mode").choice({"set", "offset"}) == 0 ? ApplyMode::kSet : ApplyMode::kOffset;
  if (f.has("integer")) {
    if (!f.at("integer").json().is_boolean()) config::fail(f.path() + ".integer", "must be true or false");
    p.integer = f.at("integer").json().get<bool>();
  }
  if (f.has("values") == f.has("range")) config::fail(f.path(), "needs exactly one of \"values\" and \"range\"");
  if (f.has("values")) {
    const Field v = f.at("values");
    const std::size_t n = v.expect_array(1, 10000);
    for (std::size_t k = 0; k < n; ++k) {
      const Field x = v.item(k);
      if (p.mode == ApplyMode::kOffset || !(x.json().is_string() || x.json().is_boolean()))
        x.number({-HUGE_VAL, HUGE_VAL});  // an offset is a number; "set" also takes strings and booleans
      p.values.push_back(x.json());
    }
  } else {
    const Eigen::Vector2d r = f.at("range").pair();
    if (!(r[0] < r[1])) config::fail(f.path() + ".range", "must be [lo, hi] with lo < hi, got [" + format_number(r[0]) + ", " + format_number(r[1]) + "]");
    p.range = std::make_pair(r[0], r[1]);
  }
  if (f.has("levels")) p.levels = f.at("levels").integer(2, 1000);
  return p;
}

Design design(const Field& f, const fs::path& study_dir, std::size_t n_parameters) {
  f.expect_object({"type", "levels", "samples", "seed", "candidates", "file"});
  Design d;
  const int kind = f.at("type").choice({"grid", "latin_hypercube", "csv"});
  d.kind = kind == 0 ? DesignKind::kGrid : kind == 1 ? DesignKind::kLatinHypercube : DesignKind::kCsv;
  const auto only_for = [&](const char* key, DesignKind k, const char* type) {
    if (f.has(key) && d.kind != k) config::fail(f.path() + "." + key, std::string("applies only to type \"") + type + "\"");
  };
  only_for("levels", DesignKind::kGrid, "grid");
  only_for("samples", DesignKind::kLatinHypercube, "latin_hypercube");
  only_for("seed", DesignKind::kLatinHypercube, "latin_hypercube");
  only_for("candidates", DesignKind::kLatinHypercube, "latin_hypercube");
  only_for("file", DesignKind::kCsv, "csv");
  if (d.kind == DesignKind::kGrid) d.levels = f.integer_or("levels", 3, 2, 1000);
  if (d.kind == DesignKind::kLatinHypercube) {
    d.samples = f.at("samples").integer(2, 100000);
    d.seed = static_cast<std::uint64_t>(f.integer_or("seed", 1, 0, 2147483647));
    d.candidates = f.integer_or("candidates", 20, 1, 1000);
  }
  if (d.kind == DesignKind::kCsv) d.csv_file = study_dir / f.at("file").string();
  if (n_parameters == 0 && d.kind != DesignKind::kCsv) config::fail("parameters", "at least one parameter is needed for a " + f.at("type").string() + " design");
  return d;
}

// Each parameter's path must name fields of the base config: applied with a value of the right kind
// (its first value, or the middle of its range), then the config parsed; a field the config does not
// know is the study's error, not every variant's refusal.
void check_paths(const Study& s) {
  for (const Parameter& p : s.parameters) {
    json doc = s.base;
    const json probe = !p.values.empty() ? p.values.front() : json(0.5 * (p.range->first + p.range->second));
    if (p.mode == ApplyMode::kOffset && !probe.is_number()) config::fail(p.field + ".values", "an offset is a number");
    apply_field(doc, p.path, p.mode, probe, p.field + ".path");
    try {
      config::parse_config(doc, s.base_dir, "probe");
    } catch (const config::ConfigError& e) {
      const std::string m = e.what();
      for (const std::string& concrete : concrete_paths(doc, p.path))
        if (m.rfind(concrete + ": unknown key", 0) == 0) config::fail(p.field + ".path", "'" + p.path.text + "': " + m);
    }
  }
}

}  // namespace

Study load_study(const fs::path& file) {
  const fs::path abs = fs::absolute(file).lexically_normal();
  const json doc = config::parse_json_document(read_file(abs, "study"), abs.filename().string());
  const Field root(doc, "");
  root.expect_object({"$schema", "name", "description", "base", "parameters", "design", "outputs"});
  Study s;
  s.file = abs;
  s.name = root.has("name") ? root.at("name").string() : abs.stem().string();
  const fs::path dir = abs.parent_path();
  const Field base = root.at("base");
  if (base.json().is_string()) {
    const fs::path config_file = (dir / base.string()).lexically_normal();
    s.base = config::parse_json_document(read_file(config_file, "base"), config_file.filename().string());
    s.base_dir = config_file.parent_path();
  } else if (base.is_object()) {
    s.base = base.json();
    s.base_dir = dir;
  } else {
    config::fail("base", "must be a config file path (relative to the study file) or a config object, got " +
                             config::json_type_name(base.json()));
  }
  if (!s.base.is_object()) config::fail("base", "the base config must be a JSON object");
  if (root.has("parameters")) {
    const Field ps = root.at("parameters");
    const std::size_t n = ps.expect_array(0, 64);
    for (std::size_t i = 0; i < n; ++i) {
      s.parameters.push_back(parameter(ps.item(i)));
      for (std::size_t k = 0; k < i; ++k)
        if (s.parameters[k].name == s.parameters[i].name)
          config::fail(ps.item(i).path() + ".name", "'" + s.parameters[i].name + "' is also the name of parameters[" + std::to_string(k) + "]");
    }
  }
  s.design = design(root.at("design"), dir, s.parameters.size());
  if (root.has("outputs")) {
    const Field o = root.at("outputs");
    const std::size_t n = o.expect_array(0, 32);
    std::vector<std::string> names;
    for (std::size_t i = 0; i < n; ++i) names.push_back(o.item(i).string());
    s.outputs = config::parse_output_formats(names, o.path());
  } else if (s.base.contains("coolant") && s.base.contains("cooling")) {
    // The coolant network is a default output of a cooled config with a "coolant" section (its headline
    // numbers are results.csv columns).
    s.outputs = config::parse_output_formats({"network"}, "outputs");
  }
  check_paths(s);
  return s;
}

}  // namespace cg::study
