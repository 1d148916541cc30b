// gearcoupling validate: a recording against a model. Metrics per channel, where the model
// fails, a terminal summary, --json, and a self-contained HTML report.
#include <fstream>
#include <optional>
#include <thread>

#include <fmt/format.h>

#include "clients/cli/before_after_summary.h"
#include "clients/cli/effect_spec.h"
#include "clients/cli/model_flags.h"
#include "clients/cli/subcommand.h"
#include "clients/cli/validation_report_html.h"
#include "clients/cli/validation_run.h"
#include "clients/cli/validation_summary.h"
#include "codec/validation_messages.h"

namespace gc::cli {
namespace {

namespace v1 = gearcoupling::v1;

std::vector<FlagSpec> validate_flags() {
  return {
      {"data", "FILE", "the recording (CSV, docs/recordings.md)", std::nullopt},
      model_flag(),
      {"reference-torque", "N·m", "T_ref: errors are also given in % of it", "1.5e6"},
      {"html", "FILE", "also write a self-contained HTML report with plots", ""},
      {"add", "EFFECT[=p=v,...]",
       "also validate the model with this effect added (SI parameters, e.g. hysteresis=lag_rad=6e-4): "
       "before and after side by side", ""},
      {"threads", "N", "threads for the model evaluations",
       std::to_string(std::max(1u, std::thread::hardware_concurrency())), false, 'j'},
  };
}

v1::RowProblemRecord to_message(const RowProblem& problem) {
  v1::RowProblemRecord record;
  record.set_line(problem.line);
  record.set_column(problem.column);
  record.set_column_name(problem.column_name);
  record.set_message(problem.message);
  return record;
}

v1::ValidationResult to_message(const RecordingSummary& recording,
                                const std::vector<ModelRun>& runs,
                                const BinningOptions& binning) {
  v1::ValidationResult result;
  result.set_recording(recording.source);
  result.set_recording_rows(recording.rows_read);
  result.set_excluded_rows(recording.excluded_rows);
  for (const RowProblem& problem : recording.problems) *result.add_row_problems() = to_message(problem);
  result.set_reference_torque_nm(binning.reference_torque_nm);
  result.set_jam_angle_rad(binning.jam_angle_rad);
  for (const ModelRun& run : runs) *result.add_models() = codec::to_message(run.name, run.validation);
  return result;
}

void write_html(const std::string& path, const v1::ValidationResult& result,
                const std::vector<ModelRun>& runs) {
  v1::ValidationReport report;
  *report.mutable_result() = result;
  for (const ModelRun& run : runs) {
    *report.add_plot_points() = codec::to_message(run.name, run.points.points());
  }
  std::ofstream file(path, std::ios::binary);
  file << validation_report_html(report);
  if (!file.flush()) throw std::runtime_error("cannot write --html " + path);
}

int run_validate(const Flags& flags, const Calculator&, std::FILE* out) {
  const codec::ModelFile model = load_model_flag(flags);
  BinningOptions binning;
  binning.reference_torque_nm = flags.number("reference-torque");
  binning.jam_angle_rad = model.model.geometry().jam_angle().angle_rad;
  std::vector<ModelRun> runs;
  runs.push_back({model.name, &model.model, ValidationAccumulator(binning), PointSampler()});
  // --add: the same recording through the model with one more effect, compared side by side.
  std::optional<CouplingModel> with_added;
  if (!flags.text("add").empty()) {
    const auto effect = parse_effect_spec(flags.text("add"));
    with_added.emplace(model.model.with_effect(effect));
    runs.push_back({model.name + " + " + effect->name(), &*with_added, ValidationAccumulator(binning),
                    PointSampler()});
  }
  const RecordingSummary recording = run_validation(
      flags.text("data"), runs, {flags.integer("threads", 1, 1024)});
  const v1::ValidationResult result = to_message(recording, runs, binning);
  if (!flags.text("html").empty()) write_html(flags.text("html"), result, runs);
  if (flags.enabled("json")) {
    print_json(result, out);
  } else {
    print_validation_summary(result, out);
    if (result.models_size() > 1) print_before_after(result, out);
    if (!flags.text("html").empty()) fmt::print(out, "\nReport: {}\n", flags.text("html"));
  }
  return 0;
}

}  // namespace

const Subcommand& validate_subcommand() {
  static const Subcommand subcommand{
      "validate",
      "Compare a recording with a model: where the model fails.\n"
      "RMSE, bias, R^2 and max error per channel, the error by torque, misalignment, "
      "direction, loading direction and time, with the worst regions in words.",
      validate_flags, run_validate};
  return subcommand;
}

}  // namespace gc::cli
