#pragma once
// Output format "network" (docs/network.md): the coolant flow network of the built part (src/network),
// solved by CalculiX: network.json, network.inp, network_results.json, film_holes.csv. Needs the config's
// "coolant" section (config.cpp checks it). A solver that is missing or does not converge is a warning
// in report.json and on stderr (the model files are written, exit 0).
#include "export/report.hpp"
#include "src/pipeline/output_writer.hpp"

namespace cg::pipeline {

/// Writes BuildResult::network; throws io::ExportError when the build made none or it has an error.
OutputWriter network_writer();

/// Adds "network" (headline numbers: status, total and per-chamber flow, worst backflow margin) and
/// the network's warnings to a report, when the build solved the network.
void add_network_report(const BuildResult& result, io::ReportContent& report);

}  // namespace cg::pipeline
