#include "analysis/model_diagnosis.h"

#include <string>

#include "analysis/effect_spec.h"
#include "codec/count_field.h"
#include "analysis/diagnosis_messages.h"

namespace gc::analysis {

gearcoupling::v1::DiagnosisResult diagnosis_result(const Diagnosis& diagnosis,
                                                   std::string_view recording_name,
                                                   std::string_view model_name,
                                                   const RecordingCheck& check,
                                                   const Recording& recording) {
  gearcoupling::v1::DiagnosisResult result = codec::to_message(diagnosis);
  result.set_recording(std::string(recording_name));
  result.set_model(std::string(model_name));
  // The core saw only the rows the reader kept: the file's malformed rows count here too, so that
  // the JSON and the text give the same counts.
  result.set_malformed_rows(codec::count_field(recording.excluded_rows, "malformed_rows"));
  result.set_recording_rows(result.recording_rows() + result.malformed_rows());
  result.set_excluded_rows(result.malformed_rows() + result.refused_rows());
  for (const std::string& warning : check.warnings) result.add_warnings(warning);
  for (const std::string& column : recording.ignored_columns) result.add_ignored_columns(column);
  for (const auto& effect : diagnosis.added) result.add_add_flags(effect_spec_text(*effect));
  return result;
}

codec::ModelFile diagnosed_model(const codec::ModelFile& file, const Diagnosis& diagnosis) {
  codec::ModelFile diagnosed = file;
  std::string added;
  for (const auto& effect : diagnosis.added) {
    diagnosed.model = diagnosed.model.with_effect(effect);
    added += (added.empty() ? "" : ", ") + effect->name();
  }
  if (added.empty()) return diagnosed;
  diagnosed.name += "_diagnosed";
  std::string& description = diagnosed.description;
  if (!description.empty() && !description.ends_with('.')) description += '.';
  description += (description.empty() ? "" : " ") + std::string("Added or refined by diagnose: ") + added + ".";
  return diagnosed;
}

}  // namespace gc::analysis
