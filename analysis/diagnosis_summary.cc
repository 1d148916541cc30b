#include "analysis/diagnosis_summary.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "analysis/table.h"
#include "core/engineering_text.h"
#include "analysis/validation_summary.h"

namespace gc::analysis {
namespace {

namespace v1 = gearcoupling::v1;

std::string parameters_text(const google::protobuf::RepeatedPtrField<v1::ParameterEstimateRecord>& parameters) {
  std::string text;
  for (const v1::ParameterEstimateRecord& p : parameters) {
    // Value and standard error under one prefix, that of the larger (a value at 0 has an error).
    const double reference = std::max(std::abs(p.value()), p.has_standard_error() ? p.standard_error() : 0.0);
    text += fmt::format("{}{} = {}", text.empty() ? "" : ", ", p.name(), engineering_text(p.value(), p.unit(), reference));
    if (p.held()) text += " (held)";
    if (p.has_standard_error()) text += " +/- " + engineering_text(p.standard_error(), p.unit(), reference);
  }
  return text;
}

/// "hysteresis", "refine friction", "formula".
std::string candidate_name(const v1::CandidateRecord& c) {
  if (c.kind() == "refinement") return "refine " + c.effect();
  if (c.kind() == "formula") return "formula";
  return c.effect();
}

void print_ranking(const v1::RoundRecord& round, std::FILE* out) {
  Table table({"rank", "candidate", "held-out RMSE [kN·m]", "change", "t", "surrogate p", "fitted parameters (search rows)"});
  const auto p_text = [](const v1::CandidateRecord& c) { return c.has_surrogate_p() ? fmt::format("{:.3f}", c.surrogate_p()) : "-"; };
  int rank = 0;
  for (const v1::CandidateRecord& c : round.ranking()) {
    if (!c.failure().empty()) {
      table.add_row({"-", candidate_name(c), "-", "-", "-", p_text(c), c.failure()});
      continue;
    }
    table.add_row({std::to_string(++rank), candidate_name(c), fmt::format("{:.2f}", c.held_out_rmse_nm() / 1e3),
                   fmt::format("{:+.0f} %", -100.0 * c.reduction()), fmt::format("{:.1f}", c.t()), p_text(c),
                   parameters_text(c.parameters())});
  }
  if (round.has_formula()) {
    const v1::CandidateRecord& f = round.formula();
    table.add_row({"-", candidate_name(f), fmt::format("{:.2f}", f.held_out_rmse_nm() / 1e3),
                   fmt::format("{:+.0f} %", -100.0 * f.reduction()), fmt::format("{:.1f}", f.t()), p_text(f),
                   parameters_text(f.parameters())});
  }
  table.print(out);
}

void print_signature(const v1::RoundRecord& round, std::FILE* out) {
  Table table({"input", "systematic", "share given the others", "share alone", "F", "trend M_sy' [N·m/unit]",
               "trend M_sz' [N·m/unit]", "moves with"});
  for (const v1::InputSignatureRecord& s : round.signature()) {
    std::string with;
    for (const std::string& c : s.confounded_with()) with += (with.empty() ? "" : ", ") + c;
    table.add_row({fmt::format("{} [{}]", s.input(), s.unit()), s.systematic() ? "yes" : "no",
                   fmt::format("{:.0f} %", 100.0 * s.explained_share()), fmt::format("{:.0f} %", 100.0 * s.marginal_share()),
                   fmt::format("{:.1f}", s.f()), format_number(s.slope_y()), format_number(s.slope_z()), with});
  }
  fmt::print(out, "\nSignature of the residual (partial dependence by input, most explaining first):\n");
  table.print(out);
}

/// Before the physics: each artefact with its channel, what it means and its rows.
void print_data_quality(const v1::DiagnosisResult& result, std::FILE* out) {
  if (result.data_quality_size() == 0) return;
  fmt::print(out, "\nData quality (before the physics):\n");
  for (const v1::DataQualityFinding& f : result.data_quality()) {
    fmt::print(out, "  - {} {}: {}\n", f.channel(), f.kind(), f.detail());
  }
}

}  // namespace

void print_diagnosis_summary(const v1::DiagnosisResult& result, std::FILE* out) {
  fmt::print(out, "Recording {}: {} rows ({} malformed, {} refused by the model), model {}; search on {} rows, "
             "refit on {}\n", result.recording(), result.recording_rows(), result.malformed_rows(),
             result.refused_rows(), result.model(), result.search_rows(), result.refit_rows());
  if (result.malformed_rows() > 0) {
    fmt::print(out, "  {} malformed rows of the file excluded ('gearcoupling validate' lists them)\n",
               result.malformed_rows());
  }
  if (result.refused_rows() > 0) fmt::print(out, "  first refusal: {}\n", result.exclusion_reason());
  if (result.outlier_rows() > 0) fmt::print(out, "  {} rows excluded as outliers (spikes)\n", result.outlier_rows());
  print_data_quality(result, out);
  if (result.rounds_size() == 0) {
    // Too few rows left after the exclusions: the summary's last line says so and why.
    const std::size_t last = result.summary().rfind('\n');
    fmt::print(out, "\n{}\n", last == std::string::npos ? result.summary() : result.summary().substr(last + 1));
  }
  for (int i = 0; i < result.rounds_size(); ++i) {
    const v1::RoundRecord& round = result.rounds(i);
    fmt::print(out, "\nRound {}: RMSE {:.2f} kN·m, noise {:.2f} kN·m (M_sy' {:.2f}, M_sz' {:.2f}; lag-1 autocorrelation {:.2f}, {:.2f})\n",
               i + 1, round.rmse_nm() / 1e3, round.noise_rmse_nm() / 1e3, round.noise_y_nm() / 1e3,
               round.noise_z_nm() / 1e3, round.noise_phi_y(), round.noise_phi_z());
    if (round.ranking_size() > 0) print_ranking(round, out);
    if (round.outcome() == "unexplained") print_signature(round, out);
    fmt::print(out, "\n{}\n", round.verdict());
  }
  for (const std::string& add : result.add_flags()) {
    // The model as the user named it: a file's path pastes where its name would not.
    fmt::print(out, "\nTo validate with it: gearcoupling validate --data {} --model {} --add {}\n",
               result.recording(), result.model_source().empty() ? result.model() : result.model_source(), add);
  }
  if (!result.written_model().empty()) fmt::print(out, "\nModel with the effects found: {}\n", result.written_model());
  print_input_notes(result.warnings(), result.ignored_columns(), out);
}

}  // namespace gc::analysis
