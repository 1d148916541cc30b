// A model's prediction of every sample of a recording, with the recording's inputs and measured
// moments and the residuals: what Model.predict returns and what ValidationResult.samples() and
// DiagnosisResult.samples() show as a DataFrame, so a user can plot where a model fails.
#pragma once

#include "clients/python/model_argument.h"
#include "clients/python/recording_argument.h"
#include "clients/python/typed_objects.h"

namespace gc::python {

/// A CaseTable, one row per sample kept (time order): time_s, torque_nm, misalignment_rad,
/// direction_rad, msy_measured_nm, msz_measured_nm, msy_predicted_nm, msz_predicted_nm,
/// msy_residual_nm, msz_residual_nm (predicted - measured: validate's sign, so their mean is its
/// bias and their RMS its RMSE), ok, error. Sample i is CouplingModel::predict_at(samples, i),
/// which takes the model's input timing (moment_delay) into account as validate does. A sample
/// the model refuses (e.g. beyond the jam angle) has NaN predictions and residuals, ok False
/// and the reason in error. All cores (threads 0), the GIL released.
CaseTableObject predict_recording(const Model& model, const Recording& recording, unsigned threads);

}  // namespace gc::python
