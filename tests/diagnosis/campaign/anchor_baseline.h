// The campaign's generic anchor ("SINDy-style"): sparse regression of the base model's residual
// on columns that know no coupling physics: polynomials (degree <= 2) of torque, misalignment,
// speed and temperature; sin/cos of beta and 2 beta times 1 and each input; harmonics 1..4 of the
// rotation phase (integrated from the logged speed), plain and times torque; the model's own
// moments, their time derivative and lagged copies (2, 4, 8, 16 samples); and sin/cos at the
// training residual's largest periodogram peaks (absolute DAQ time). Sequentially thresholded
// ridge least squares, blocked cross-validation over contiguous blocks, the one-standard-error
// rule (the sparsest threshold within one standard error of the best). Raw time enters only
// through the Fourier columns: a polynomial in time extrapolates without bound into a later run.
#pragma once

#include <string>
#include <vector>

#include <Eigen/Dense>

#include "core/measurement_sample.h"
#include "tests/diagnosis/campaign/programme.h"

namespace gc::campaign {

struct AnchorChannel {
  Eigen::VectorXd coefficients;
  double threshold_nm = 0.0;
  double ridge = 0.0;
  int active_terms = 0;
};

struct AnchorModel {
  std::vector<double> fourier_hz;                 ///< the periodogram peaks kept
  Eigen::VectorXd input_lo, input_hi;             ///< T, zeta, speed, temperature (training)
  Eigen::VectorXd column_mean, column_scale;
  std::vector<std::string> terms;
  AnchorChannel y, z;
};

/// `inputs` the logged rows (phase integrated from the logged speed), `model` the base model's
/// moments at them, `measured` the measured moments; rows in time order, malformed rows left out.
AnchorModel fit_anchor(const std::vector<InputRow>& inputs, const std::vector<SensorMoments>& model,
                       const std::vector<SensorMoments>& measured);

/// The anchor's prediction of the measured moments: model + fitted residual.
std::vector<SensorMoments> predict_anchor(const AnchorModel& a, const std::vector<InputRow>& inputs,
                                          const std::vector<SensorMoments>& model);

/// A summary of the active terms, e.g. "y: 3 terms (cos(2phase), ...)".
std::string describe_anchor(const AnchorModel& a);

}  // namespace gc::campaign
