// Where the fits of thermal_misalignment and eccentricity start, from the recording: the
// misalignment vector the residual asks for, as a line in an input.
//
// Both effects add a vector to the measured misalignment that is linear in one input x:
//   thermal_misalignment  g (theta - theta_0) along beta_t           (x the oil temperature),
//   eccentricity          zeta_e (1 - T / (s T_m)) along gravity     (x the torque, below s T_m, k = 1),
// that is q (x - x0), with q = g along beta_t and x0 = theta_0, or q = -zeta_e / (s T_m) along
// gravity and x0 = s T_m. Over a recording whose x spans a small part of |x - x0| the added vector
// is mostly constant with a slope on it, and in the effects' own parameters (g, theta_0; zeta_e,
// s) the cost is a long curved valley, their product nearly constant: descents from the box's
// probes stopped with x0 inside the recorded range, a vector that changes sign within it, and
// assembly_misalignment took the claim (noise zoo power seed 20261267, draw 0: a growth of
// 21.5 urad/degC aligned at 22.2 degC, the oil at 38-52 degC, fitted -26.8 urad/degC from
// 35.6 degC, RMSE 6.87 kN·m; the truth 6.28 kN·m; the assembly offset 6.37 kN·m).
//
// The line is found where the cost is nearly quadratic: in the vector itself. With J_y, J_z the
// moments' response to a unit misalignment added along beta = 0 and beta = pi/2 (finite
// differences of the model, row by row):
//   1. the constant vector a the residual asks for, by Gauss-Newton from none (a vector of the size
//      of the measured misalignment bends the response, so it is taken again at a);
//   2. there, least squares on [J_y, J_z, J_y tau, J_z tau], tau = x minus its mean, gives the
//      vector at the mean and its slope b; the line's point along b where it vanishes is
//      x0 = mean - (a . b / |b|) / |b|;
//   3. Gauss-Newton on the line q (x - x0), in (q, x0), at the model with the effect itself (the
//      moments moving by J (x - x0) dq - J q dx0).
// A step that does not lower the sum of squares is halved, three times at most. The effect's
// parameters from the line are a start of its fit (FitSettings::hints), as a moment delay starts
// from cross-correlation (delay_estimate.h). From it the draw above fits 19.2 urad/degC from
// 19.4 degC at 2.48 rad, held out 6.29 kN·m against the assembly offset's 6.35.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "core/coupling_model.h"
#include "core/effects/effect_registry.h"
#include "core/recorded_sample.h"
#include "diagnosis/parallel_for.h"

namespace gc {

/// thermal_misalignment's growth_rad_per_c, reference_temperature_c and direction_rad (within the
/// effect's bounds) from the lines in the oil temperature that bring `model` nearest the measured
/// moments of observations[rows], one for each step of the finite differences; none when
/// `library` lacks thermal_misalignment, fewer than 16 rows have a temperature and a prediction,
/// or the temperature spans less than 0.5 degC. About 50 evaluations of the model on the rows.
std::vector<ParameterValues> thermal_growth_starts(const CouplingModel& model, std::span<const RecordedSample> observations,
                                                    std::span<const std::size_t> rows,
                                                    const std::vector<EffectRegistration>& library,
                                                    const ParallelFor& parallel);

/// eccentricity's eccentric_misalignment_rad, threshold_scale and gravity_direction_rad (within
/// the effect's bounds) from the lines in the recorded torque, the fade linear (k = 1, the default
/// of a first fit); none as above, with the torque spanning less than 5 % of T_m.
std::vector<ParameterValues> eccentricity_starts(const CouplingModel& model, std::span<const RecordedSample> observations,
                                                  std::span<const std::size_t> rows,
                                                  const std::vector<EffectRegistration>& library,
                                                  const ParallelFor& parallel);

/// Every line q (x - x0) of `effect`'s input (the oil temperature for thermal_misalignment, the
/// torque for eccentricity) linearised at `model`: the columns J_y, J_z, J_y tau, J_z tau (tau = x
/// less its mean over the rows) stacked as the channels over `rows` (k for M_sy', n + k for M_sz';
/// zero where a row has no x, which the effect leaves alone). The fit of either effect starts from
/// the line the residual asks for, a search over the whole family, so the surrogate test scans
/// this design beside the fit's (surrogate_claims.cc, effect_design): the null is searched as the
/// residual was. nullopt for any other effect, or where `model` cannot predict a row.
std::optional<Eigen::MatrixXd> misalignment_line_design(const std::string& effect, const CouplingModel& model,
                                                       std::span<const RecordedSample> observations,
                                                       std::span<const std::size_t> rows, const ParallelFor& parallel);

}  // namespace gc
