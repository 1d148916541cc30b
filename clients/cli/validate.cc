// gearcoupling validate: a recording against a model. Metrics per channel, where the model
// fails, a terminal summary, --json, and a self-contained HTML report.
#include <thread>

#include <fmt/format.h>

#include "analysis/before_after_summary.h"
#include "analysis/model_validation.h"
#include "analysis/scale_check.h"
#include "analysis/validation_report_html.h"
#include "analysis/validation_result.h"
#include "analysis/validation_run.h"
#include "analysis/validation_summary.h"
#include "clients/cli/jobs_flag.h"
#include "clients/cli/model_flags.h"
#include "clients/cli/recording_flags.h"
#include "clients/cli/subcommand.h"

namespace gc::cli {
namespace {

using analysis::ModelRun;
using analysis::print_before_after;
using analysis::print_validation_summary;

namespace v1 = gearcoupling::v1;

std::vector<FlagSpec> validate_flags() {
  std::vector<FlagSpec> flags = {
      {"data", "FILE", "the recording (CSV, docs/recordings.md)", std::nullopt},
      model_flag(),
      columns_flag(),
      negate_flag(),
      force_scale_flag(),
      {"reference-torque-nm", "N·m", "T_ref: errors are also given in % of it (default: the model's friction T_ref, else 1.5e6)", "1.5e6", false,
       '\0', {"reference-torque"}},
      {"html", "FILE", "also write a self-contained HTML report with plots", ""},
      {"add", "EFFECT[=p=v,...]",
       "also validate the model with this effect added (SI parameters, e.g. hysteresis=lag_rad=6e-4): "
       "before and after side by side", ""},
      jobs_flag(),
  };
  append(flags, {catalogue_flag(), json_flag()});
  append(flags, refused_calculator_flags("validate"));
  return flags;
}

int run_validate(const Flags& flags, const Calculator&, std::FILE* out) {
  const codec::ModelFile model = load_model_flag(flags);
  const double reference_torque_nm = flags.given("reference-torque-nm")
                                         ? flags.number("reference-torque-nm")
                                         : analysis::model_reference_torque(model, flags.number("reference-torque-nm"));
  const auto validation = analysis::validate_model(
      flags.text("data"), model, flags.text("add"), reference_torque_nm,
      {jobs_from(flags), 1u << 15, column_renames(flags), negated_quantities(flags)});
  if (!validation->note.empty()) fmt::print(stderr, "gearcoupling validate: note: {}\n", validation->note);
  const v1::ValidationResult& result = validation->result;
  const std::vector<ModelRun>& runs = validation->runs;
  print_recording_notes("validate", {result.ignored_columns().begin(), result.ignored_columns().end()},
                        {result.warnings().begin(), result.warnings().end()});
  analysis::require_compared_samples(result);
  if (!flags.enabled("force-scale")) {
    analysis::refuse_unit_slip(flags.text("data"), runs.front().scale.refusal(runs.front().name));
  }
  if (!flags.text("html").empty()) {
    analysis::write_validation_report(flags.text("html"), analysis::validation_report(result, runs));
  }
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
