// One round of the diagnosis (docs/diagnosis.md): the model's residual, its noise and signature,
// the time terms; when it is more than noise, the candidates ranked and put through the claim rule,
// the formula weighed against the best effect, and the round's outcome.
#pragma once

#include <cstddef>
#include <map>
#include <set>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "core/coupling_model.h"
#include "core/recorded_sample.h"
#include "diagnosis/cross_validation_folds.h"
#include "diagnosis/diagnose.h"
#include "diagnosis/formula_search.h"
#include "diagnosis/parallel_for.h"

namespace gc {

/// The formula stage's settings in `round`: the settings' own, with the round's noise correlation
/// and time terms.
FormulaSettings formula_settings(const DiagnosisRound& round, const DiagnosisSettings& settings);

/// One round: residual, noise, signature, candidates, outcome.
/// `residual`: the model's on `rows`.
DiagnosisRound search_round(const CouplingModel& model, const Eigen::MatrixX2d& residual,
                            std::span<const RecordedSample> observations, const std::vector<std::size_t>& rows,
                            const std::vector<std::size_t>& search, const std::vector<std::size_t>& signature_rows,
                            const Folds& folds, const ParallelFor& parallel, const CouplingModel& given,
                            const std::set<std::string>& partly, const std::map<std::string, std::string>& rivals,
                            const DiagnosisSettings& settings);

}  // namespace gc
