#pragma once
// The hand-off part of the CLI: the output files of `coolinggen build` beside report.json, and the
// `coolinggen mesh` command. Kept apart from main.cpp so the build job can move into a library
// (src/pipeline) without touching this logic.
#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

#include "export/report.hpp"
#include "src/brep/blade_solid.hpp"
#include "src/config/config.hpp"

namespace cg::cli {

/// Writes the selected outputs of config.output (blade.step ... sections.svg) for the part made of
/// `solid` and returns the summary for report.json ("outputs").
nlohmann::json write_build_outputs(const std::filesystem::path& dir, const config::Config& config,
                                   const blade::BladeModel& model, const brep::BladeSolid& solid);

/// Writes report.json (report_json(content) plus `extra` keys such as "outputs" and "mesh") and,
/// when `markdown`, report.md rendered from the same document. Returns the paths written.
std::vector<std::filesystem::path> write_reports(const std::filesystem::path& dir, const io::ReportContent& content,
                                                 const nlohmann::json& extra, bool markdown);

/// `coolinggen mesh [CONFIG] -o DIR`: builds and verifies the solid, meshes metal and coolant with the
/// config's "mesh" options, writes the mesh files, report.json ("mesh" statistics) and report.md.
/// Progress goes to stderr only when it is a terminal and not `quiet`. Returns the exit code.
int run_mesh(const std::string& config_path, const std::filesystem::path& out_dir, bool quiet);

}  // namespace cg::cli
