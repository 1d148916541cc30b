// gearcoupling diagnose: which effect of the library the model lacks (docs/diagnosis.md).
#include <fstream>
#include <thread>

#include <fmt/format.h>

#include "clients/cli/diagnosis_summary.h"
#include "clients/cli/model_flags.h"
#include "clients/cli/recording_csv.h"
#include "clients/cli/subcommand.h"
#include "codec/diagnosis_messages.h"
#include "core/diagnosis/diagnose.h"
#include "parallel/thread_parallel_for.h"

namespace gc::cli {
namespace {

std::vector<FlagSpec> diagnose_flags() {
  return {
      {"data", "FILE", "the recording (CSV, docs/recordings.md)", std::nullopt},
      model_flag(),
      {"write-model", "FILE", "also write the model with the effects found (text format)", ""},
      {"threads", "N", "threads for the model evaluations",
       std::to_string(std::max(1u, std::thread::hardware_concurrency())), false, 'j'},
  };
}

/// The model with every effect the diagnosis added, as a model file.
void write_model(const std::string& path, const codec::ModelFile& file, const Diagnosis& diagnosis) {
  CouplingModel model = file.model;
  std::string added;
  for (const auto& effect : diagnosis.added) {
    model = model.with_effect(effect);
    added += (added.empty() ? "" : ", ") + effect->name();
  }
  std::ofstream out(path, std::ios::binary);
  std::string description = file.description;
  if (!added.empty()) {
    if (!description.empty() && !description.ends_with('.')) description += '.';
    description += (description.empty() ? "" : " ") + std::string("Added or refined by diagnose: ") + added + ".";
  }
  out << codec::write_model_text(file.name + (added.empty() ? "" : "_diagnosed"), description, file.coupling, model);
  if (!out.flush()) throw std::runtime_error("cannot write --write-model " + path);
}

int run_diagnose(const Flags& flags, const Calculator&, std::FILE* out) {
  const codec::ModelFile model = load_model_flag(flags);
  const Recording recording = read_recording(flags.text("data"));
  const Diagnosis diagnosis =
      diagnose(model.model, recording.samples, thread_parallel_for(flags.integer("threads", 1, 1024)));
  gearcoupling::v1::DiagnosisResult result = codec::to_message(diagnosis);
  result.set_recording(flags.text("data"));
  result.set_model(model.name);
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
