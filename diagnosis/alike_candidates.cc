#include "diagnosis/alike_candidates.h"

#include "diagnosis/claim_rule.h"
#include "diagnosis/separating_experiment.h"

namespace gc {
namespace {

/// Cosine of the angle between two candidates' corrections to the base model (uncentred, so
/// two constant offsets count as alike).
double correction_similarity(const Eigen::MatrixX2d& base, const Eigen::MatrixX2d& a, const Eigen::MatrixX2d& b) {
  const Eigen::MatrixX2d ca = base - a, cb = base - b;
  const double denominator = ca.norm() * cb.norm();
  return denominator > 0.0 ? (ca.array() * cb.array()).sum() / denominator : 0.0;
}

/// `model` with the candidate's effect, and without the earlier claims it replaces.
CouplingModel model_with_candidate(const CouplingModel& model, const CandidateScore& c) {
  CouplingModel out = model;
  for (const std::string& name : c.replaces) out = out.without_effect(name);
  return out.with_effect(c.fit->effect);
}

}  // namespace

bool alike(const CandidateScore& best, const CandidateScore& other, const Eigen::MatrixX2d& base,
           const Folds& folds, const DiagnosisSettings& settings, double& similarity, PairedBlockTest& t) {
  similarity = correction_similarity(base, best.held_out_residual, other.held_out_residual);
  t = paired_block_test(other.held_out_residual, best.held_out_residual, folds.block_of, folds.blocks);
  const bool close = other.held_out_rmse_nm <= (1.0 + settings.alike_rmse_share) * best.held_out_rmse_nm;
  return similarity >= settings.alike_correlation && (close || t.t < settings.alike_t);
}

std::vector<AlikeEffect> alike_effects(const CouplingModel& model, const std::vector<CandidateScore>& ranking,
                                       const Eigen::MatrixX2d& base, const Folds& folds, double base_ms,
                                       double noise_ms, std::span<const RecordedSample> observations,
                                       const std::vector<std::size_t>& rows, double noise_sigma,
                                       const DiagnosisSettings& settings) {
  std::vector<AlikeEffect> out;
  const CandidateScore& best = ranking.front();
  for (std::size_t k = 1; k < ranking.size(); ++k) {
    const CandidateScore& other = ranking[k];
    if (!claimable(other, base_ms, noise_ms, settings) || !plausible(other) || other.info->name == best.info->name) continue;
    double similarity = 0.0;
    PairedBlockTest t;
    if (!alike(best, other, base, folds, settings, similarity, t)) continue;
    out.push_back({other.info->name, similarity, t,
                   separating_experiment(model_with_candidate(model, best), model_with_candidate(model, other),
                                         observations, rows, noise_sigma)});
  }
  return out;
}

}  // namespace gc
