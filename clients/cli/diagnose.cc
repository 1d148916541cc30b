// gearcoupling diagnose: which effect of the library the model lacks (docs/diagnosis.md).
#include <thread>

#include <fmt/format.h>

#include "analysis/atomic_file.h"
#include "analysis/diagnosis_summary.h"
#include "analysis/effect_spec.h"
#include "analysis/recording_csv.h"
#include "analysis/validation_result.h"
#include "clients/cli/jobs_flag.h"
#include "clients/cli/model_flags.h"
#include "clients/cli/recording_flags.h"
#include "clients/cli/subcommand.h"
#include "codec/diagnosis_messages.h"
#include "core/diagnosis/diagnose.h"
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
      {"write-model", "FILE", "also write the model with the effects found (text format)", ""},
      jobs_flag(),
  };
  append(flags, {catalogue_flag(), json_flag()});
  append(flags, refused_calculator_flags("diagnose"));
  return flags;
}

/// The model with every effect the diagnosis added, as a model file.
void write_model(const std::string& path, const codec::ModelFile& file, const Diagnosis& diagnosis) {
  CouplingModel model = file.model;
  std::string added;
  for (const auto& effect : diagnosis.added) {
    model = model.with_effect(effect);
    added += (added.empty() ? "" : ", ") + effect->name();
  }
  std::string description = file.description;
  if (!added.empty()) {
    if (!description.empty() && !description.ends_with('.')) description += '.';
    description += (description.empty() ? "" : " ") + std::string("Added or refined by diagnose: ") + added + ".";
  }
  analysis::write_file_atomically(
      path, codec::write_model_text(file.name + (added.empty() ? "" : "_diagnosed"), description, file.coupling, model),
      "--write-model");
}

int run_diagnose(const Flags& flags, const Calculator&, std::FILE* out) {
  const codec::ModelFile model = load_model_flag(flags);
  const Recording recording = read_recording(flags.text("data"), analysis::RecordingOptions{{}, column_renames(flags)});
  const analysis::RecordingCheck check = analysis::check_recording(model.model, model.name, recording.samples);
  print_recording_notes("diagnose", recording.ignored_columns, check.warnings);
  analysis::require_compared_samples(flags.text("data"), model.name, check.compared, recording.rows_read,
                                     recording.excluded_rows, recording.samples.size(), check.first_refusal);
  const Diagnosis diagnosis =
      diagnose(model.model, recording.samples, thread_parallel_for(jobs_from(flags)));
  gearcoupling::v1::DiagnosisResult result = codec::to_message(diagnosis);
  result.set_recording(flags.text("data"));
  result.set_model(model.name);
  for (const std::string& warning : check.warnings) result.add_warnings(warning);
  for (const std::string& column : recording.ignored_columns) result.add_ignored_columns(column);
  for (const auto& effect : diagnosis.added) result.add_add_flags(analysis::effect_spec_text(*effect));
  if (!flags.text("write-model").empty()) {
    write_model(flags.text("write-model"), model, diagnosis);
    result.set_written_model(flags.text("write-model"));
  }
  if (flags.enabled("json")) {
    print_json(result, out);
  } else {
    print_diagnosis_summary(result, out);
    if (recording.excluded_rows > 0) {
      fmt::print(out, "\n{} malformed rows of the file were excluded ('gearcoupling validate' lists them)\n",
                 recording.excluded_rows);
    }
  }
  return 0;
}

}  // namespace

const Subcommand& diagnose_subcommand() {
  static const Subcommand subcommand{
      "diagnose",
      "Which effect of the library the model lacks: fit each, rank by held-out error.\n"
      "Every effect the model does not have is fitted on training folds and scored on held-out "
      "folds; the best is claimed only when its gain is significant against the noise, then the "
      "search runs again. Says when the residual is noise, and shows its signature when no "
      "effect explains it.",
      diagnose_flags, run_diagnose};
  return subcommand;
}

}  // namespace gc::cli
