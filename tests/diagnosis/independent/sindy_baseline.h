// The generic baseline issue 8 measures the diagnosis against: sparse regression of the base
// model's residual on a fixed library of terms in the raw inputs (SINDy; Brunton, Proctor, Kutz,
// PNAS 2016), with no physics of couplings. If a diagnosis cannot beat this on held-out data, its
// physics bought nothing.
#pragma once

#include <span>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "core/measurement_sample.h"

namespace gc::independent {

struct SindySettings {
  int max_degree = 3;             ///< polynomial terms of T, zeta, time (speed, temperature) up to this
  int trig_product_degree = 2;    ///< sin/cos of beta and 2 beta, times monomials up to this degree
  /// Ridge per row on the unit-variance columns [-], chosen by the same cross-validation: the
  /// library is strongly collinear (speed and temperature are smooth in time), and with a ridge of
  /// 1e-6 alone the full fit extrapolates wildly into held-out time blocks.
  std::vector<double> ridges = {1e-6, 1e-4, 1e-3, 1e-2};
  int stlsq_iterations = 10;
  int thresholds = 25;            ///< log-spaced from 1e-3 to 1 x the residual's std, plus 0
  int folds = 5;
  int blocks = 50;                ///< contiguous time blocks, dealt to the folds round-robin
};

/// One channel's sparse model: coefficients on the normalised library columns.
struct SindyChannel {
  Eigen::VectorXd coefficients;   ///< [N·m per unit column]
  double ridge = 0.0;             ///< the cross-validated choice, per row [-]
  double threshold_nm = 0.0;      ///< the one-standard-error choice
  int active_terms = 0;
  double cv_rmse_nm = 0.0;        ///< cross-validated RMSE at that threshold
};

struct SindyModel {
  SindySettings settings;          ///< as fitted
  std::vector<std::string> terms;  ///< column names, e.g. "T*zeta*sin(beta)"
  bool uses_speed = false;         ///< every training sample had a speed
  bool uses_temperature = false;   ///< ... a temperature
  Eigen::VectorXd input_offset, input_scale;    ///< raw input -> [-1, 1] (training min and max)
  Eigen::VectorXd column_mean, column_scale;    ///< library column -> unit variance (training)
  SindyChannel y, z;
};

/// Fits the residual (measured - base model) of each channel separately: STLSQ (sequential
/// thresholded ridge least squares) at every ridge and threshold, scored by blocked
/// cross-validation; the ridge of the lowest error, the sparsest threshold within one standard
/// error of its best, then refitted on all rows. Column normalisation is from all training rows.
/// `inputs` and `residual` are the same rows in time order.
SindyModel fit_sindy(std::span<const MeasurementSample> inputs, std::span<const SensorMoments> residual,
                     const SindySettings& settings = {});

/// The fitted residual at new inputs [N·m] (to subtract from the base model's residual).
std::vector<SensorMoments> predict_sindy(const SindyModel& model, std::span<const MeasurementSample> inputs);

}  // namespace gc::independent
