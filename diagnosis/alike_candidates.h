// Candidates the data cannot tell apart: corrections that point the same way and held-out errors
// within a small share of each other or not significantly different. What an "indistinguishable"
// verdict lists, each with the experiment that would separate it from the best.
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
#include "diagnosis/paired_block_test.h"

namespace gc {

/// Alike: corrections that point the same way, and held-out errors within a small share of each
/// other or not significantly different.
bool alike(const CandidateScore& best, const CandidateScore& other, const Eigen::MatrixX2d& base,
           const Folds& folds, const DiagnosisSettings& settings, double& similarity, PairedBlockTest& t);

/// The claimable, plausible candidates of `ranking` alike to its first, each with the experiment
/// that tells the two apart (separating_experiment.h) on `rows`.
std::vector<AlikeEffect> alike_effects(const CouplingModel& model, const std::vector<CandidateScore>& ranking,
                                       const Eigen::MatrixX2d& base, const Folds& folds, double base_ms,
                                       double noise_ms, std::span<const RecordedSample> observations,
                                       const std::vector<std::size_t>& rows, double noise_sigma,
                                       const DiagnosisSettings& settings);

}  // namespace gc
