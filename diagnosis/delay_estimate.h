// How late the moment channels are against the inputs, from the recording alone: the delay tau
// that brings the model's moment sequence onto the measured one,
//   tau* = argmin over tau of sum_i |M_measured(t_i) - M_model(t_i - tau)|^2,
// with M_model(t - tau) interpolated linearly in the model's own sequence of predictions (the
// measured moments minus the residual), the classic cross-correlation estimate of a skew. It costs
// no model evaluation, and it sees every dense row, where a fit of moment_delay on the search rows
// sees a transient (a torque step) in one row of four: the fit starts from it (FitSettings::hints).
#pragma once

#include <optional>
#include <span>

#include <Eigen/Dense>

#include "core/recorded_sample.h"
#include "diagnosis/parallel_for.h"

namespace gc {

/// The delay [s] within [-1 s, 2 s] (steps of half the rows' typical spacing) that lowers the summed
/// squares of `residual` (rows k of observations[rows[k]], in time order) the most; nullopt when no
/// delay lowers them by 1 % or more. The delays are tried side by side with `parallel`.
std::optional<double> moment_delay_estimate(std::span<const RecordedSample> observations,
                                            std::span<const std::size_t> rows, const Eigen::MatrixX2d& residual,
                                            const ParallelFor& parallel);

}  // namespace gc
