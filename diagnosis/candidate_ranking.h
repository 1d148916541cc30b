// The round's candidates ranked (docs/diagnosis.md): every effect of the library the model lacks
// and the search rows have the inputs for, every effect to refine (the given model's, those held
// in a shape, those said to explain only partly), and the partly claims refitted together, with a
// rival in a member's place; scored side by side on held-out folds, by held-out RMSE, failures last.
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
#include "diagnosis/candidate_score.h"
#include "diagnosis/cross_validation_folds.h"
#include "diagnosis/diagnose.h"
#include "diagnosis/parallel_for.h"

namespace gc {

/// `model` the round's, `given` the model the diagnosis started from; `base` the round's residual on
/// `search`; `partly` the effects said to explain only partly, `rivals` their rivals
/// (rival_of_claim); `hints` starts for the fits beside the settings' own.
std::vector<CandidateScore> rank_candidates(const CouplingModel& model, std::span<const RecordedSample> observations,
                                            const std::vector<std::size_t>& search, const Eigen::MatrixX2d& base,
                                            const Folds& folds, const ParallelFor& parallel,
                                            const CouplingModel& given, const std::set<std::string>& partly,
                                            const std::map<std::string, std::string>& rivals,
                                            const DiagnosisSettings& given_settings,
                                            const std::vector<ParameterValues>& hints);

}  // namespace gc
