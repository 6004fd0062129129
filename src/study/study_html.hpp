#pragma once
// DIR/study_report.html: one offline page of a study's results (export/web/study_page.js draws it): the
// status counts, the refusals by field, each swept parameter against each metric coloured by status,
// parallel coordinates, and the variants' table; every point links to its variant's report.html when
// the variant wrote one (the study's outputs include html), else to its report.json.
#include <filesystem>

#include "src/study/results.hpp"

namespace cg::study {

/// Writes DIR/study_report.html atomically. Throws io::ExportError.
void write_study_html(const std::filesystem::path& study_dir, const StudyListing& listing);

}  // namespace cg::study
