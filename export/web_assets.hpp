#pragma once
// The committed web assets of the HTML reports (export/web/), embedded at build time by
// cmake/EmbedText.cmake: the viewer (three.js, GLTFLoader, OrbitControls bundled into one classic
// script by esbuild, export/web/README.md), the build and study reports' page scripts and the pages'
// style.
namespace cg::io::web {

extern const char* const kViewerBundle;  ///< export/web/viewer.bundle.js: defines window.CoolingGenViewer
extern const char* const kReportPage;    ///< export/web/report_page.js
extern const char* const kStudyPage;     ///< export/web/study_page.js
extern const char* const kPageStyle;     ///< export/web/report.css

}  // namespace cg::io::web
