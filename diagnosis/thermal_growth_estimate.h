// Where a fit of thermal_misalignment starts, from the recording: the misalignment vector the
// residual asks for, as a line in the oil temperature.
//
// The effect adds g (theta - theta_0) along beta_t (core/effects/thermal_misalignment.cc). Over a
// test whose oil moves 15 degC about 45 degC, a growth aligned at 22 degC is mostly a constant
// vector with a slope on it, and in (g, theta_0) the cost is a long curved valley (g times
// theta - theta_0 nearly constant): descents from the box's probes stop with theta_0 inside the
// recorded range, a vector that changes sign within it, and assembly_misalignment takes the claim
// although a growth from 22 degC fits to the noise floor (noise zoo power seed 20261267, draw 0:
// fitted -26.8 urad/degC from 35.6 degC at 0.18 rad, RMSE 6.87 kN·m; the truth, 21.5 urad/degC from
// 22.2 degC at 2.49 rad, 6.28 kN·m; the assembly offset 6.37 kN·m).
//
// The vector is found where the cost is nearly quadratic: in the vector itself. With J_y, J_z the
// moments' response to a unit misalignment added along beta = 0 and beta = pi/2 (finite
// differences of the model, row by row):
//   1. the constant vector a the residual asks for, by Gauss-Newton from none (a vector of the size
//      of the measured misalignment bends the response, so the response is taken again at a);
//   2. there, least squares on [J_y, J_z, J_y tau, J_z tau], tau = theta minus its mean, gives the
//      vector at the mean temperature and its slope b; the line's point along b where it vanishes
//      is theta_0 = mean - (a . b / |b|) / |b|;
//   3. Gauss-Newton on the line q (theta - theta_0), in (q, theta_0), the moments moving by
//      J (theta - theta_0) dq - J q dtheta_0.
// Each step that does not lower the sum of squares is halved. The result is g = |q|, beta_t the
// direction of q, and theta_0: a start of the effect's fit (FitSettings::hints), as a moment delay
// starts from cross-correlation (delay_estimate.h). From it the draw above fits 19.2 urad/degC from
// 19.4 degC at 2.48 rad, held out 6.29 kN·m against the assembly offset's 6.35.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include <Eigen/Dense>

#include "core/coupling_model.h"
#include "core/effects/effect_registry.h"
#include "core/recorded_sample.h"
#include "diagnosis/parallel_for.h"

namespace gc {

/// growth_rad_per_c, reference_temperature_c and direction_rad of thermal_misalignment that bring
/// `model` nearest the measured moments of observations[rows], the reference kept within
/// [-40, 150] degC; nullopt when `library` has no assembly_misalignment (the probe) or
/// thermal_misalignment, fewer than 16 rows have a temperature and a prediction, or the temperature
/// spans less than 0.5 degC. About 25 evaluations of the model on the rows.
std::optional<ParameterValues> thermal_growth_estimate(const CouplingModel& model,
                                                       std::span<const RecordedSample> observations,
                                                       std::span<const std::size_t> rows,
                                                       const std::vector<EffectRegistration>& library,
                                                       const ParallelFor& parallel);

}  // namespace gc
