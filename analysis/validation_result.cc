#include "analysis/validation_result.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "analysis/input_names.h"
#include "codec/count_field.h"
#include "analysis/validation_messages.h"
#include "core/model_error.h"

namespace gc::analysis {
namespace {

namespace v1 = gearcoupling::v1;

v1::RowProblemRecord to_message(const RowProblem& problem) {
  v1::RowProblemRecord record;
  record.set_line(static_cast<std::int32_t>(codec::count_field(static_cast<std::size_t>(problem.line), "row_problems.line")));
  record.set_column(problem.column);
  record.set_column_name(problem.column_name);
  record.set_message(problem.message);
  return record;
}

void add_warnings(const std::vector<std::string>& warnings,
                  google::protobuf::RepeatedPtrField<std::string>& out) {
  for (const std::string& warning : warnings) *out.Add() = warning;
}

}  // namespace

v1::ValidationResult validation_result(const RecordingSummary& recording,
                                       const std::vector<ModelRun>& runs,
                                       const BinningOptions& binning) {
  v1::ValidationResult result;
  result.set_recording(recording.source);
  result.set_recording_rows(codec::count_field(recording.rows_read, "recording_rows"));
  result.set_excluded_rows(codec::count_field(recording.excluded_rows, "excluded_rows"));
  for (const RowProblem& problem : recording.problems) *result.add_row_problems() = to_message(problem);
  for (const std::string& column : recording.ignored_columns) result.add_ignored_columns(column);
  result.set_reference_torque_nm(binning.reference_torque_nm);
  result.set_jam_angle_rad(binning.jam_angle_rad);
  for (const ModelRun& run : runs) {
    *result.add_models() = codec::to_message(run.name, run.validation);
    add_warnings(run.scale.warnings(run.name), *result.mutable_warnings());
  }
  if (auto warning = misalignment_scale_warning(recording.largest_misalignment_rad, binning.jam_angle_rad)) {
    result.add_warnings(*warning);
  }
  if (auto warning = torque_scale_warning(recording.largest_torque_nm, binning.reference_torque_nm)) {
    result.add_warnings(*warning);
  }
  return result;
}

void require_compared_samples(std::string_view source, std::string_view model_name,
                              std::size_t compared, std::size_t rows, std::size_t excluded_rows,
                              std::size_t refused, std::string_view first_refusal, UnitFix fix) {
  if (compared > 0) return;
  std::string why;
  if (rows == 0) {
    why = "the file has no data rows";
  } else if (excluded_rows == rows) {
    why = fmt::format("all {} rows were excluded as malformed", rows);
  } else {
    why = fmt::format("the model refused all {} samples read (first: {})", refused, first_refusal);
    if (refuses_negative_torque("operating_point.torque_nm", first_refusal)) {
      why += negative_torque_hint(fix == UnitFix::python
                                      ? "for a dyno that logs the drive torque negative, read the "
                                        "column with negate=\"torque\""
                                      : "for a dyno that logs the drive torque negative, read the "
                                        "column with --negate torque");
    }
  }
  throw InvalidInput("recording", fmt::format("{}: {} compared no sample: {}; an RMSE of no "
                                              "samples is no fit", source, model_name, why));
}

void require_compared_samples(const v1::ValidationResult& result, UnitFix fix) {
  for (const v1::ModelValidation& model : result.models()) {
    const std::string first_refusal =
        model.rejections_size() > 0 ? model.rejections(0).field() + ": " + model.rejections(0).first_message() : "";
    require_compared_samples(result.recording(), model.model(), model.compared_samples(),
                             result.recording_rows(), result.excluded_rows(),
                             model.rejected_samples(), first_refusal, fix);
  }
}

RecordingCheck check_recording(const CouplingModel& model, std::string_view model_name,
                               const std::vector<RecordedSample>& samples) {
  RecordingCheck check;
  MomentScale scale;
  double largest_misalignment_rad = 0.0, largest_torque_nm = 0.0;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const RecordedSample& sample = samples[i];
    largest_misalignment_rad = std::max(largest_misalignment_rad, std::abs(sample.input.misalignment_rad));
    largest_torque_nm = std::max(largest_torque_nm, std::abs(sample.input.torque_nm));
    try {
      scale.add(sample.measured, model.predict_at(std::span<const RecordedSample>(samples), i).moments);
      ++check.compared;
    } catch (const InvalidInput& error) {
      if (check.first_refusal.empty()) check.first_refusal = error.field() + ": " + error.what();
    } catch (const ModelError& error) {
      if (check.first_refusal.empty()) check.first_refusal = std::string("model: ") + error.what();
    }
  }
  check.warnings = scale.warnings(model_name);
  check.refusal = scale.refusal(model_name);
  if (auto warning = misalignment_scale_warning(largest_misalignment_rad,
                                                model.geometry().jam_angle().angle_rad)) {
    check.warnings.push_back(*warning);
  }
  // T_ref as validate's default: check_recording is not given one.
  if (auto warning = torque_scale_warning(largest_torque_nm, BinningOptions{}.reference_torque_nm)) {
    check.warnings.push_back(*warning);
  }
  return check;
}

}  // namespace gc::analysis
