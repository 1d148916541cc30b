#include "analysis/validation_report_html.h"

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "analysis/atomic_file.h"
#include "analysis/report_scale.h"
#include "codec/result_json.h"
#include "analysis/validation_messages.h"
#include "validation_report_js.h"  // kValidationReportJs, generated from validation_report.js

namespace gc::analysis {
namespace {

constexpr std::string_view kStyle = R"css(
body { font-family: "DejaVu Sans", Arial, sans-serif; margin: 24px; color: #222; max-width: 1500px; }
h1 { font-size: 24px; } h2 { font-size: 20px; margin-top: 32px; border-bottom: 1px solid #ccc; }
.note { color: #555; } li { margin: 4px 0; }
.grid { display: grid; grid-template-columns: 1fr 1fr; gap: 16px; }
.chart { height: 340px; border: 1px solid #ddd; padding: 6px; }
table { border-collapse: collapse; margin: 8px 0; }
th, td { border: 1px solid #ccc; padding: 4px 8px; text-align: right; font-size: 13px; }
.maps { display: grid; grid-template-columns: 1fr 1fr; gap: 16px; }
caption { font-weight: bold; padding: 4px; }
.scale { display: flex; align-items: center; gap: 8px; margin: 8px 0; }
.scale .bar { position: relative; width: 320px; height: 16px; border: 1px solid #ccc;
  background: linear-gradient(to right, rgba(214,39,40,0.05), rgba(214,39,40,0.9)); }
.scale .noise { position: absolute; top: -4px; bottom: -4px; width: 3px; background: #000; }
)css";

std::string read_file(const std::filesystem::path& path) {
  errno = 0;
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw std::runtime_error("cannot read Chart.js at " + path.string() + ": " + std::strerror(errno) +
                             " (install Debian's libjs-chart.js, or set $GEARCOUPLING_CHART_JS)");
  }
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// Text inside <script> must not close it: "</" becomes "<\/", the same string in JavaScript.
std::string script_safe(std::string text) {
  for (std::size_t at = text.find("</"); at != std::string::npos; at = text.find("</", at + 3)) {
    text.replace(at, 2, "<\\/");
  }
  return text;
}

}  // namespace

std::filesystem::path chart_js_path() {
  const char* path = std::getenv("GEARCOUPLING_CHART_JS");
  return path != nullptr && *path != '\0' ? std::filesystem::path(path)
                                          : std::filesystem::path(GC_CHART_JS);
}

std::string chart_js() { return read_file(chart_js_path()); }

std::string validation_report_html(const gearcoupling::v1::ValidationReport& report) {
  std::string html = "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n";
  html += "<title>gearcoupling validate: " + report.result().recording() + "</title>\n<style>";
  html += kStyle;
  html += "</style>\n<script>\n" + script_safe(chart_js()) + "\n</script>\n";
  html += "</head>\n<body>\n<div id=\"main\"></div>\n<script>\nconst DATA = ";
  html += script_safe(codec::to_json(report));
  html += ";\n" + script_safe(std::string(kValidationReportJs)) + "\n</script>\n</body>\n</html>\n";
  return html;
}

gearcoupling::v1::ValidationReport validation_report(const gearcoupling::v1::ValidationResult& result,
                                                     const std::vector<ModelRun>& runs) {
  gearcoupling::v1::ValidationReport report;
  *report.mutable_result() = result;
  for (const ModelRun& run : runs) {
    *report.add_plot_points() = codec::to_message(run.name, run.points.points());
  }
  report.set_colour_scale_max_nm(colour_scale_max_nm(result));
  report.set_noise_level_nm(noise_level_nm(result));
  return report;
}

void write_validation_report(const std::filesystem::path& path,
                             const gearcoupling::v1::ValidationReport& report) {
  write_file_atomically(path, validation_report_html(report), "--html");
}

}  // namespace gc::analysis
