#include "src/config/output_format.hpp"

#include <algorithm>

#include "src/config/config_error.hpp"

namespace cg::config {

const char* output_format_name(OutputFormat format) {
  for (const OutputFormatInfo& f : kOutputFormats)
    if (f.format == format) return f.name;
  return "?";  // unreachable: every value has a row (tests/cli/test_config.cpp)
}

std::string output_format_names() {
  std::string names;
  for (const OutputFormatInfo& f : kOutputFormats) names += (names.empty() ? "\"" : ", \"") + std::string(f.name) + "\"";
  return names;
}

std::vector<OutputFormat> default_output_formats() {
  std::vector<OutputFormat> out;
  for (const OutputFormatInfo& f : kOutputFormats)
    if (f.by_default == DefaultOutput::Written) out.push_back(f.format);
  return out;
}

std::vector<OutputFormat> parse_output_formats(const std::vector<std::string>& names, const std::string& field) {
  std::vector<OutputFormat> out;
  for (std::size_t i = 0; i < names.size(); ++i) {
    const std::string path = field + "[" + std::to_string(i) + "]";
    const auto* f = std::find_if(std::begin(kOutputFormats), std::end(kOutputFormats),
                                 [&](const OutputFormatInfo& x) { return names[i] == x.name; });
    if (f == std::end(kOutputFormats))
      throw ConfigError(path + ": unknown output format \"" + names[i] + "\" (allowed: " + output_format_names() + ")");
    if (has_format(out, f->format)) throw ConfigError(path + ": \"" + names[i] + "\" is listed twice");
    out.push_back(f->format);
  }
  return out;
}

std::vector<std::string> output_format_names(const std::vector<OutputFormat>& formats) {
  std::vector<std::string> out;
  for (OutputFormat f : formats) out.push_back(output_format_name(f));
  return out;
}

bool has_format(const std::vector<OutputFormat>& formats, OutputFormat format) {
  return std::find(formats.begin(), formats.end(), format) != formats.end();
}

}  // namespace cg::config
