// gearcoupling diagnose: which effect of the library the model lacks (docs/diagnosis.md).
#include <thread>

#include <fmt/format.h>

#include "analysis/atomic_file.h"
#include "analysis/diagnosis_summary.h"
#include "analysis/model_diagnosis.h"
#include "analysis/recording_csv.h"
#include "analysis/scale_check.h"
#include "analysis/validation_result.h"
#include "clients/cli/jobs_flag.h"
#include "clients/cli/model_flags.h"
#include "clients/cli/recording_flags.h"
#include "clients/cli/subcommand.h"
#include "diagnosis/diagnose.h"
#include "parallel/thread_parallel_for.h"

namespace gc::cli {

using analysis::Recording;
using analysis::print_diagnosis_summary;
using analysis::read_recording;
namespace {

std::vector<FlagSpec> diagnose_flags() {
  std::vector<FlagSpec> flags = {
      {"data", "FILE", "the recording (CSV, docs/recordings.md)", std::nullopt},
      model_flag(),
      columns_flag(),
      negate_flag(),
      force_scale_flag(),
      {"write-model", "FILE", "also write the model with the effects found (text format)", ""},
      jobs_flag(),
  };
  append(flags, {catalogue_flag(), json_flag()});
  append(flags, refused_calculator_flags("diagnose"));
  return flags;
}

/// The model with every effect the diagnosis added, as a model file.
void write_model(const std::string& path, const codec::ModelFile& file, const Diagnosis& diagnosis) {
  const codec::ModelFile diagnosed = analysis::diagnosed_model(file, diagnosis);
  analysis::write_file_atomically(
      path, codec::write_model_text(diagnosed.name, diagnosed.description, diagnosed.coupling, diagnosed.model),
      "--write-model");
}

int run_diagnose(const Flags& flags, const Calculator&, std::FILE* out) {
  const codec::ModelFile model = load_model_flag(flags);
  const Recording recording = read_recording(flags.text("data"), analysis::RecordingOptions{{}, column_renames(flags), negated_quantities(flags)});
  const analysis::RecordingCheck check = analysis::check_recording(model.model, model.name, recording.samples);
  print_recording_notes("diagnose", recording.ignored_columns, check.warnings);
  analysis::require_compared_samples(flags.text("data"), model.name, check.compared, recording.rows_read,
                                     recording.excluded_rows, recording.samples.size(), check.first_refusal);
  if (!flags.enabled("force-scale")) analysis::refuse_unit_slip(flags.text("data"), check.refusal);
  const Diagnosis diagnosis =
      diagnose(model.model, recording.samples, thread_parallel_for(jobs_from(flags)));
  gearcoupling::v1::DiagnosisResult result =
      analysis::diagnosis_result(diagnosis, flags.text("data"), model.name, check, recording);
  result.set_model_source(flags.text("model"));
  if (!flags.text("write-model").empty()) {
    write_model(flags.text("write-model"), model, diagnosis);
    result.set_written_model(flags.text("write-model"));
  }
  if (flags.enabled("json")) {
    print_json(result, out);
  } else {
    print_diagnosis_summary(result, out);
  }
  return 0;
}

}  // namespace

const Subcommand& diagnose_subcommand() {
  static const Subcommand subcommand{
      "diagnose",
      "What the model lacks: an effect of the library, a refinement of one it has, or a formula.\n"
      "Each round scores three kinds of candidate on held-out blocks of the recording: every effect "
      "of the library the model does not have and the recording has the inputs for (moment_delay "
      "among them: moment channels that lag the inputs), every effect it has with its parameters "
      "freed (and those this diagnosis added, refitted together when one was only partly right), and "
      "a formula of physical terms (torque, misalignment, speed, temperature, rates, the model's own "
      "moments, shaft orders on one channel or as a whirl, cycles at any frequency, steps at a "
      "time), each with the mechanisms it usually means. The best "
      "is claimed only when its gain is significant against the noise as the recording has it "
      "(coloured, heavy-tailed, wandering); a value outside its plausible range is advice on what to "
      "check, not a veto. Then earlier claims are revisited and the search runs again. Says when "
      "the residual is noise, and shows its signature when nothing explains it.",
      diagnose_flags, run_diagnose};
  return subcommand;
}

}  // namespace gc::cli
