// Which of the ranked candidates a round would claim, moved to the front of the ranking: plausible
// before implausible unless significantly worse, and of candidates alike on held-out rows, the one
// with fewer parameters (a simpler swap of an earlier claim, or the simplest alike effect, plausible
// or not: among candidates the data cannot tell apart, fewer fitted parameters outrank a plausible
// range).
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

/// Of the claimable effects alike to the one ranked first (alike()) and not held on a physical
/// bound, the one with the fewest fitted parameters goes first: where the data cannot tell two
/// apart, the simpler model, plausible or not.
/// - An assembly misalignment (two parameters) and a thermal misalignment (more) fit a recording at
///   a nearly steady oil temperature alike; the simpler says as much with less.
/// - At a steady torque a torque gain of 10.6 % scales the moments as a gain and offset of both
///   channels does (four parameters, the gains within their plausible 10 %): the torque
///   calibration, its slope at 0.050 just past its plausible 5 %, is named (power table seed
///   20261270, draw 0; a compliance at 0.50 of eq 5, below its plausible 0.6, likewise).
/// - A parameter held at the model's value (the data could not determine it) is not fitted: a
///   refined friction with its reference torque and misalignment share held fits two, against a
///   gain and offset's four (power table seed 20261278, draw 5).
void put_simplest_alike_first(std::vector<CandidateScore>& ranking, const Eigen::MatrixX2d& base, const Folds& folds,
                              double base_ms, double noise_ms, const DiagnosisSettings& settings);

}  // namespace gc
