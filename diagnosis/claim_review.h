// Claims revisited (backward elimination): after each round's claim, every earlier claim is tested
// again with the new one in place, and one that no longer earns its place is dropped. An offset
// that took the mean of a drift in round 1 is no longer needed once round 2's formula has the drift,
// or a fresh formula takes it over.
#pragma once

#include <memory>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "core/coupling_model.h"
#include "diagnosis/cross_validation_folds.h"
#include "diagnosis/diagnose.h"
#include "diagnosis/parallel_for.h"
#include "core/recorded_sample.h"

namespace gc {

/// Of the effects named in `earlier` (all in `model`), those whose removal does not make the model
/// worse on held-out blocks: the residual of `model` without one, on `rows` (no parameter refitted
/// to make up for it), against `held_out` (the model's held-out residual on `rows` as the folds cut
/// them) has a block-paired t below `keep_t`. Removal without refitting favours keeping, so a
/// dropped claim was truly idle. Effects whose removal leaves rows the model cannot predict are kept.
std::vector<std::string> redundant_claims(const CouplingModel& model, const std::vector<std::string>& earlier,
                                          const Eigen::MatrixX2d& held_out,
                                          std::span<const RecordedSample> observations,
                                          std::span<const std::size_t> rows, const Folds& folds,
                                          const ParallelFor& parallel, double keep_t);

/// After the round's claim is in `model`: drops the earlier claims (in `added`) it makes idle, and,
/// when the claim is a formula, those a fresh formula can take over (the claim becomes that formula).
/// Refinements of the given model's effects are refined again later, never removed.
void revisit_claims(CouplingModel& model, DiagnosisRound& round, std::vector<std::shared_ptr<const Effect>>& added,
                    const CouplingModel& given, std::span<const RecordedSample> observations,
                    const std::vector<std::size_t>& search, const std::vector<std::size_t>& refit, const Folds& folds,
                    const ParallelFor& parallel, const DiagnosisSettings& settings);

}  // namespace gc
