// Which of the ranked candidates a round would claim, moved to the front of the ranking: plausible
// before implausible unless significantly worse, and of candidates alike on held-out rows, the one
// with fewer parameters (a simpler swap of an earlier claim, or the simplest alike effect).
#pragma once

#include <vector>

#include <Eigen/Dense>

#include "diagnosis/candidate_score.h"
#include "diagnosis/cross_validation_folds.h"
#include "diagnosis/diagnose.h"

namespace gc {

/// Moves the effect to claim to the front: the best plausible one unless an implausible one is
/// significantly better (then it is claimed as partly explaining).
void put_claim_first(std::vector<CandidateScore>& ranking, double base_ms, double noise_ms, const Folds& folds,
                     const DiagnosisSettings& settings);

/// A swap (CandidateScore::replaces) that does as well as the candidate ranked first, on fewer
/// parameters, goes first: alike on held-out rows (within alike_rmse_share, or not significantly
/// worse), the simpler model. A joint refit of a thermal growth and a channel gain and offset (7
/// parameters) and the same with the self-weight in the place of the gain and offset (4) both
/// reached the truth's growth, 1.95 against 1.97 kN·m held out.
void put_simpler_swap_first(std::vector<CandidateScore>& ranking, const Folds& folds, const DiagnosisSettings& settings);

/// Of the claimable, plausible effects alike to the one ranked first (alike()), the one with the
/// fewest parameters goes first: where the data cannot tell two apart, the simpler model. An
/// assembly misalignment (two parameters) and a thermal misalignment (more) fit a recording at a
/// nearly steady oil temperature alike; the simpler says as much with less.
void put_simplest_alike_first(std::vector<CandidateScore>& ranking, const Eigen::MatrixX2d& base, const Folds& folds,
                              double base_ms, double noise_ms, const DiagnosisSettings& settings);

}  // namespace gc
