// Rows left out before the physics is diagnosed, from the base model's residual: spikes (outliers)
// and the rows of a moment channel whose sign turned. Each leaves the rows in use and their residual.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include <Eigen/Dense>

#include "core/coupling_model.h"
#include "core/recorded_sample.h"
#include "diagnosis/diagnose.h"
#include "diagnosis/parallel_for.h"

namespace gc {

/// Spikes are measurement faults, not physics: removed from `rows` (in time order) and `residual`
/// once, from the base model's residual. Returns them (indices into the recording). A moment
/// channel rounded to an ADC step (quantisation.h) is judged against its rounding noise at least.
std::vector<std::size_t> exclude_outliers(std::span<const RecordedSample> observations, std::vector<std::size_t>& rows,
                                          Eigen::MatrixX2d& residual, double deviations);

/// A moment channel whose sign turned (polarity_flip.h) measured the coupling with the wrong sign:
/// its rows leave `rows` and `residual` and join the data-quality findings.
void exclude_moment_flips(Diagnosis& out, std::span<const RecordedSample> observations, std::vector<std::size_t>& rows,
                          Eigen::MatrixX2d& residual);

/// Rows where the model jumps within the input sensors' noise (model_jumps.h): they leave `rows`
/// and `residual` and join the data-quality findings.
void exclude_rows_at_model_jumps(Diagnosis& out, const CouplingModel& model, std::span<const RecordedSample> observations,
                                 std::vector<std::size_t>& rows, Eigen::MatrixX2d& residual, const ParallelFor& parallel);

}  // namespace gc
