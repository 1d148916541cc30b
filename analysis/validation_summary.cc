#include "analysis/validation_summary.h"

#include <algorithm>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "analysis/table.h"
#include "core/engineering_text.h"

namespace gc::analysis {
namespace {

namespace v1 = gearcoupling::v1;

constexpr std::size_t kProblemsShown = 10;

void add_metrics_row(Table& table, const std::string& model, std::string_view channel,
                     const v1::ErrorMetricsRecord& m) {
  table.add_row({model, std::string(channel), std::to_string(m.count()),
                 fmt::format("{:.2f}", m.rmse_nm() / 1e3), fmt::format("{:+.2f}", m.bias_nm() / 1e3),
                 m.has_r_squared() ? fmt::format("{:.4f}", m.r_squared()) : "n/a",
                 fmt::format("{:.2f}", m.max_abs_error_nm() / 1e3)});
}

void print_metrics(const v1::ValidationResult& result, std::FILE* out) {
  // kN·m throughout, as the HTML report: a percentage of T_ref hides the scale of the error.
  Table table({"model", "channel", "samples", "RMSE [kN·m]", "bias [kN·m]", "R^2",
               "max |err| [kN·m]"});
  for (const v1::ModelValidation& model : result.models()) {
    add_metrics_row(table, model.model(), "M_sy'", model.overall().msy());
    add_metrics_row(table, model.model(), "M_sz'", model.overall().msz());
  }
  table.print(out);
}

// "by direction 99 %, by time 12 %": the inputs whose bins explain at least 10 % of the error.
std::string shares_text(const v1::ErrorSignatureRecord& signature) {
  std::vector<std::pair<double, std::string>> shares;
  for (const auto& share : signature.shares()) {
    if (share.explained_share() >= 0.1) shares.emplace_back(share.explained_share(), share.dimension());
  }
  std::sort(shares.rbegin(), shares.rend());
  std::string text;
  for (const auto& [share, dimension] : shares) {
    text += fmt::format("{}{} {:.0f} %", text.empty() ? "" : ", ", dimension, 100.0 * share);
  }
  return text.empty() ? "no single input (under 10 % each)" : text;
}

void print_signature(const v1::ModelValidation& model, const v1::ErrorSignatureRecord& signature,
                     std::FILE* out) {
  const auto& metrics = signature.channel() == "M_sy'" ? model.overall().msy() : model.overall().msz();
  if (metrics.count() == 0) {
    fmt::print(out, "  {}: no sample compared.\n", signature.channel());
    return;
  }
  if (signature.at_noise_level()) {
    fmt::print(out, "  {}: at the noise level: RMSE {:.2f} kN·m against a noise estimate of "
               "{:.2f} kN·m; no systematic error to locate.\n", signature.channel(),
               metrics.rmse_nm() / 1e3, signature.noise_estimate_nm() / 1e3);
    return;
  }
  fmt::print(out, "  {}: RMSE {:.2f} kN·m = noise {:.2f} kN·m (+) systematic {:.2f} kN·m; the "
             "bin biases of these inputs explain it: {}.\n", signature.channel(),
             metrics.rmse_nm() / 1e3, signature.noise_estimate_nm() / 1e3,
             signature.systematic_rms_nm() / 1e3, shares_text(signature));
  for (const v1::RegionRecord& region : model.worst_regions()) {
    if (region.channel() != signature.channel() || region.contrast() < kNotableContrast) continue;
    fmt::print(out, "    [{:4.1f}x] {}\n", region.contrast(), region.description());
  }
}

void print_regions(const v1::ModelValidation& model, std::FILE* out) {
  fmt::print(out, "\nWhere {} fails ([contrast] = RMSE in the region / RMSE elsewhere; regions "
             "from {:.2f}x):\n", model.model(), kNotableContrast);
  for (const auto& signature : model.signatures()) print_signature(model, signature, out);
}

void print_rejections(const v1::ModelValidation& model, std::FILE* out) {
  if (model.rejected_samples() == 0) return;
  fmt::print(out, "\n{} of the samples refused by {} (not in the metrics):\n",
             model.rejected_samples(), model.model());
  for (const v1::RejectionRecord& r : model.rejections()) {
    fmt::print(out, "  {} x {} (first at t = {} s: {})\n", r.count(), r.field(),
               r.first_time_s(), r.first_message());
  }
}

void print_row_problems(const v1::ValidationResult& result, std::FILE* out) {
  if (result.excluded_rows() == 0) return;
  fmt::print(out, "\n{} of {} rows of {} excluded as malformed:\n", result.excluded_rows(),
             result.recording_rows(), result.recording());
  for (int i = 0; i < result.row_problems_size() && i < static_cast<int>(kProblemsShown); ++i) {
    const v1::RowProblemRecord& p = result.row_problems(i);
    fmt::print(out, "  line {}{}: {}\n", p.line(),
               p.column() > 0 ? fmt::format(", column {} ({})", p.column(), p.column_name()) : "",
               p.message());
  }
  if (result.excluded_rows() > kProblemsShown) {
    fmt::print(out, "  ... and {} more (--json lists the first {})\n",
               result.excluded_rows() - kProblemsShown, result.row_problems_size());
  }
}

}  // namespace

void print_input_notes(const google::protobuf::RepeatedPtrField<std::string>& warnings,
                       const google::protobuf::RepeatedPtrField<std::string>& ignored_columns,
                       std::FILE* out) {
  if (!ignored_columns.empty()) {
    std::string names;
    for (const std::string& column : ignored_columns) names += (names.empty() ? "" : ", ") + column;
    fmt::print(out, "\nIgnored columns (no known quantity): {}\n", names);
  }
  if (warnings.empty()) return;
  fmt::print(out, "\nWarnings (a unit in the header, most likely):\n");
  for (const std::string& warning : warnings) fmt::print(out, "  {}\n", warning);
}

void print_validation_summary(const v1::ValidationResult& result, std::FILE* out) {
  fmt::print(out, "Recording {}: {} rows; reference torque T_ref {}; errors are model - "
             "measurement\n\n", result.recording(), result.recording_rows(),
             engineering_text(result.reference_torque_nm(), "N·m"));
  print_metrics(result, out);
  for (const v1::ModelValidation& model : result.models()) {
    print_regions(model, out);
    print_rejections(model, out);
  }
  print_row_problems(result, out);
  print_input_notes(result.warnings(), result.ignored_columns(), out);
}

}  // namespace gc::analysis
