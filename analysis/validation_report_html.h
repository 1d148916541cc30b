// validate's HTML report: one self-contained file that opens offline. The data (a
// gearcoupling.v1.ValidationReport as protobuf JSON), the page script (validation_report.js)
// and Chart.js (Debian's libjs-chart.js, read at generation time) are all inlined.
#pragma once

#include <filesystem>
#include <string>

#include <vector>

#include "analysis/validation_run.h"
#include "idl/validation.pb.h"

namespace gc::analysis {

/// The path of Chart.js: $GEARCOUPLING_CHART_JS when set, else Debian's libjs-chart.js.
std::filesystem::path chart_js_path();

/// The text of Chart.js (chart_js_path()), for a page to inline or a server to serve. Throws
/// std::runtime_error naming the file and the package when it cannot be read.
std::string chart_js();

/// The whole page. Throws std::runtime_error naming the file when Chart.js cannot be read.
std::string validation_report_html(const gearcoupling::v1::ValidationReport& report);

/// The report's data: the result, each model's plotted points, and the one colour scale of its
/// error maps with the noise level (analysis/report_scale.h).
gearcoupling::v1::ValidationReport validation_report(const gearcoupling::v1::ValidationResult& result,
                                                     const std::vector<ModelRun>& runs);

/// The page, written whole or not at all (analysis/atomic_file.h). Throws std::runtime_error
/// naming --html and the path.
void write_validation_report(const std::filesystem::path& path,
                             const gearcoupling::v1::ValidationReport& report);

}  // namespace gc::analysis
