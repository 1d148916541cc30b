// diagnose's result and the model it finds, shared by the CLI (gearcoupling diagnose) and
// Python (gearcoupling.diagnose).
#pragma once

#include <string_view>

#include "analysis/recording_csv.h"
#include "analysis/validation_result.h"
#include "codec/model_file.h"
#include "diagnosis/diagnose.h"
#include "idl/diagnosis.pb.h"

namespace gc::analysis {

/// The diagnosis as data (analysis/diagnosis_messages.h) with the recording's name, the model's,
/// the recording check's scale warnings and the recording's ignored columns.
gearcoupling::v1::DiagnosisResult diagnosis_result(const Diagnosis& diagnosis,
                                                   std::string_view recording_name,
                                                   std::string_view model_name,
                                                   const RecordingCheck& check,
                                                   const Recording& recording);

/// `file`'s model with every effect the diagnosis added, named "<name>_diagnosed" and described
/// with what was added (unchanged when nothing was).
codec::ModelFile diagnosed_model(const codec::ModelFile& file, const Diagnosis& diagnosis);

}  // namespace gc::analysis
