// validate's result as data (gearcoupling.v1.ValidationResult, idl/validation.proto): what the
// terminal summary, --json and the HTML report show, and what the monitor and Python read.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "analysis/scale_check.h"
#include "analysis/validation_run.h"
#include "core/coupling_model.h"
#include "idl/validation.pb.h"

namespace gc::analysis {

/// The recording's counts, problems and ignored columns, each model's errors, and the scale
/// warnings (analysis/scale_check.h) of every model and of the misalignment.
gearcoupling::v1::ValidationResult validation_result(const RecordingSummary& recording,
                                                     const std::vector<ModelRun>& runs,
                                                     const BinningOptions& binning);

/// Zero compared samples is no data, not a perfect fit (an RMSE of 0.00). Throws InvalidInput
/// naming "recording" with why: no rows, every row malformed, or every sample refused (with
/// the model's first reason). A negative torque gets the fix in `fix`'s terms (--negate torque,
/// or Python's negate="torque").
void require_compared_samples(const gearcoupling::v1::ValidationResult& result,
                              UnitFix fix = UnitFix::cli);

/// What the same check finds for a recording in memory (diagnose): the samples `model`
/// accepts, the first refusal, and the scale warnings. Predicts every sample once.
struct RecordingCheck {
  std::size_t compared = 0;
  std::string first_refusal;          ///< "field: message" of the first refused sample
  std::vector<std::string> warnings;
  std::optional<std::string> refusal;   ///< MomentScale::refusal: a channel 1000 times off
};
RecordingCheck check_recording(const CouplingModel& model, std::string_view model_name,
                               const std::vector<RecordedSample>& samples);

/// The error of require_compared_samples for `source` when `compared` is zero.
void require_compared_samples(std::string_view source, std::string_view model_name,
                              std::size_t compared, std::size_t rows, std::size_t excluded_rows,
                              std::size_t refused, std::string_view first_refusal,
                              UnitFix fix = UnitFix::cli);

}  // namespace gc::analysis
