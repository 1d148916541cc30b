// The claim rule's second test (docs/diagnosis.md, "The claim rule"): a weak claim must stand out of
// the noise's slow wander (slow_wander.h) and carry to a fifth of the recording it was not fitted
// on (whole_fifths.h); what leaks from a slow noise through interleaved folds does neither.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include <Eigen/Dense>

#include "core/coupling_model.h"
#include "core/recorded_sample.h"
#include "diagnosis/candidate_score.h"
#include "diagnosis/cross_validation_folds.h"
#include "diagnosis/diagnose.h"
#include "diagnosis/parallel_for.h"

namespace gc {

/// The formula's terms refitted on four contiguous fifths and judged on the fifth it never saw.
bool formula_carries(const CandidateScore& formula, std::span<const RecordedSample> observations,
                     std::span<const std::size_t> rows, const Eigen::MatrixX2d& base, const Folds& fifths);

/// Whether a formula's edge over an effect carries to whole fifths: each refitted on four
/// contiguous fifths, the formula better on the fifth neither saw (whole_fifths.h: a paired t of
/// kWholeFifthsT with the noise's long-run inflation). What a formula's extra terms take from a slow
/// noise through the interleaved folds does not (a weight's offset with two terms beside it that
/// followed a zero wandering over 5.7 s of a 12.5 s recording, t = 3.7 interleaved). False for an
/// effect that is not refitted alone (a joint refit, a swap).
bool formula_edge_carries(const CandidateScore& formula, const CandidateScore& effect, const CouplingModel& model,
                          std::span<const RecordedSample> observations, const std::vector<std::size_t>& search,
                          const Eigen::MatrixX2d& base, const Folds& fifths, const ParallelFor& parallel,
                          const DiagnosisSettings& settings);

/// The claim rule's second test on the effect that would be claimed: one that does not carry to
/// whole fifths is marked failed and goes last, and the next claimable one is tried, until one
/// carries or none is claimable (each test costs a fit; only where the best do not carry).
void demote_what_does_not_carry(std::vector<CandidateScore>& ranking, const CouplingModel& model,
                                std::span<const RecordedSample> observations, const std::vector<std::size_t>& search,
                                const Eigen::MatrixX2d& base, const Folds& fifths, const ParallelFor& parallel,
                                double base_ms, double noise_ms, const DiagnosisSettings& settings);

}  // namespace gc
