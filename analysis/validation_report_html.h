// validate's HTML report: one self-contained file that opens offline. The data (a
// gearcoupling.v1.ValidationReport as protobuf JSON), the page script (validation_report.js)
// and Chart.js (Debian's libjs-chart.js, read at generation time) are all inlined.
#pragma once

#include <filesystem>
#include <string>

#include "idl/validation.pb.h"

namespace gc::cli {

/// The path of Chart.js: $GEARCOUPLING_CHART_JS when set, else Debian's libjs-chart.js.
std::filesystem::path chart_js_path();

/// The whole page. Throws std::runtime_error naming the file when Chart.js cannot be read.
std::string validation_report_html(const gearcoupling::v1::ValidationReport& report);

}  // namespace gc::cli
