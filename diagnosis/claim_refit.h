// The round's claim refitted on the refit rows (at most DiagnosisSettings::refit_rows, evenly spaced
// in time), from its fit on the search rows: the parameters and their uncertainties the diagnosis
// reports, and the model the next round searches from.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include <Eigen/Dense>

#include "core/coupling_model.h"
#include "core/recorded_sample.h"
#include "diagnosis/diagnose.h"
#include "diagnosis/effect_fit.h"
#include "diagnosis/parallel_for.h"

namespace gc {

/// The round's claim refitted on the refit rows (an effect from its search fit; a formula by least
/// squares), or nullopt when the refit cannot predict those rows.
std::optional<EffectFit> refit_claim(const CouplingModel& model, const DiagnosisRound& round,
                                     std::span<const RecordedSample> observations, const std::vector<std::size_t>& rows,
                                     const Eigen::MatrixX2d& residual, const std::vector<std::size_t>& refit,
                                     const ParallelFor& parallel, const DiagnosisSettings& settings);

}  // namespace gc
