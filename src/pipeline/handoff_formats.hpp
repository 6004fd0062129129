#pragma once
// The hand-off output formats after STEP (README, Outputs): iges, brep, stl, vtk, glb, preview,
// sections, html, report_md, as entries of output_writers(). They share one triangulation (stl, vtk,
// preview), one viewing model (glb, html) and one set of section cuts (sections, html, report_md,
// report.json) per build result, made in the background from the start of write_outputs or on first use.
#include <vector>

#include "export/report.hpp"
#include "src/pipeline/outputs.hpp"

namespace cg::pipeline {

/// The entries, in the order they are written (report_md last, so it lists every model file).
std::vector<OutputWriter> handoff_writers();

/// Adds the hand-off sections to a report: "sections" (passage area, wetted perimeter and hydraulic
/// diameter along span, when the sections were cut in this run) and "notes" (outputs skipped and why).
void add_handoff_report(const config::Config& config, const BuildResult& result, io::ReportContent& report);

/// Starts the shared triangulation and section cuts of the selected formats in the background, at the
/// lowest priority (write_outputs calls it once the STEP file is written; the IGES writer, which uses
/// one core, runs beside them): the formats then pick up the finished work.
void prepare_shared_outputs(const config::Config& config, const BuildResult& result);
/// Waits for the background work of `result` (before the result may go away).
void finish_shared_outputs(const BuildResult& result) noexcept;

}  // namespace cg::pipeline
