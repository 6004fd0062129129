#pragma once
// The files a build can write, named by "output.formats" (README, Outputs), defined once here: the
// enum, the names users write and which are written by default. The pipeline (src/pipeline/outputs.cpp)
// has one writer per value; data/schema/coolinggen.schema.json lists the same names (a test compares).
// A new format: a value and its row in kOutputFormats (the order formats are written), its writer, its
// name in the schema.
#include <string>
#include <vector>

namespace cg::config {

enum class OutputFormat { Step, Iges, Brep, Stl, Vtk, Glb, Preview, Sections, GeomTurbo, Network, Html, ReportMd };

enum class DefaultOutput { Written, OnRequest };

struct OutputFormatInfo {
  OutputFormat format;
  const char* name;          ///< as written in output.formats
  DefaultOutput by_default;  ///< part of the default list of `build`
};

/// Every format, in the order they are written (report_md last: it lists the files written before it).
inline constexpr OutputFormatInfo kOutputFormats[] = {
    {OutputFormat::Step, "step", DefaultOutput::Written},
    {OutputFormat::Iges, "iges", DefaultOutput::Written},
    {OutputFormat::Brep, "brep", DefaultOutput::Written},
    {OutputFormat::Stl, "stl", DefaultOutput::Written},
    {OutputFormat::Vtk, "vtk", DefaultOutput::Written},
    {OutputFormat::Glb, "glb", DefaultOutput::Written},
    {OutputFormat::Preview, "preview", DefaultOutput::Written},
    {OutputFormat::Sections, "sections", DefaultOutput::Written},
    {OutputFormat::GeomTurbo, "geomturbo", DefaultOutput::OnRequest},
    // The network before html and report_md, so that both show its results. Written by default when the
    // config has a "coolant" section (config.cpp), on request otherwise.
    {OutputFormat::Network, "network", DefaultOutput::OnRequest},
    {OutputFormat::Html, "html", DefaultOutput::Written},
    {OutputFormat::ReportMd, "report_md", DefaultOutput::Written},
};

/// The name users write ("step").
const char* output_format_name(OutputFormat format);
/// "\"step\", \"iges\", ...": every name, in order, for messages.
std::string output_format_names();
/// The formats `build` writes when the config has no output.formats.
std::vector<OutputFormat> default_output_formats();
/// Names -> formats; ConfigError "<field>[i]: unknown output format \"x\" (allowed: ...)" for a name no
/// format has, "<field>[i]: \"x\" is listed twice" for a repeat.
std::vector<OutputFormat> parse_output_formats(const std::vector<std::string>& names, const std::string& field);
/// Formats -> names (a variant's config, the report's copy of what was asked).
std::vector<std::string> output_format_names(const std::vector<OutputFormat>& formats);
/// Whether `formats` lists `format`.
bool has_format(const std::vector<OutputFormat>& formats, OutputFormat format);

}  // namespace cg::config
