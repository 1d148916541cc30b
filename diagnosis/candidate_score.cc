#include "diagnosis/candidate_score.h"

#include <algorithm>
#include <cmath>

#include "diagnosis/model_residuals.h"
#include "diagnosis/noise_estimate.h"
#include "diagnosis/row_selection.h"

namespace gc {
namespace {

/// Fits on the fold's training rows (warm start) and returns the residual on its held-out rows,
/// or a reason it could not.
std::optional<Eigen::MatrixX2d> held_out_residual(const CouplingModel& base, const EffectRegistration& registration,
                                                  const EffectFit& full, std::span<const RecordedSample> observations,
                                                  const std::vector<std::size_t>& training,
                                                  const std::vector<std::size_t>& held_out,
                                                  const ParallelFor& parallel, int iterations, int& evaluations) {
  const std::optional<EffectFit> fold =
      refit_effect(base, registration, full, observations, training, parallel, iterations, false);
  if (!fold) return std::nullopt;
  evaluations += fold->evaluations;
  const ModelResiduals r = model_residuals(base.with_effect(fold->effect), observations, held_out, parallel);
  ++evaluations;
  if (!r.failed_rows.empty()) return std::nullopt;
  return r.residual;
}

}  // namespace

CandidateScore score_candidate(const CouplingModel& base, const EffectRegistration& registration,
                               std::span<const RecordedSample> observations, std::span<const std::size_t> rows,
                               const Eigen::MatrixX2d& base_residual, const Folds& folds,
                               const ParallelFor& parallel, const CrossValidationSettings& settings,
                               const Effect* current) {
  CandidateScore score;
  score.kind = current ? CandidateKind::refinement : CandidateKind::addition;
  score.info = registration.info;
  score.fit = fit_effect(base, registration, observations, rows, parallel, settings.fit, current);
  if (!score.fit) {
    score.failure = "no parameter values within the bounds let the model predict every row";
    return score;
  }
  score.evaluations = score.fit->evaluations;
  score.held_out_residual = Eigen::MatrixX2d::Zero(static_cast<Eigen::Index>(rows.size()), 2);
  for (std::size_t f = 0; f < folds.held_out.size(); ++f) {
    const auto r = held_out_residual(base, registration, *score.fit, observations, rows_at(rows, folds.training[f]),
                                     rows_at(rows, folds.held_out[f]), parallel, settings.fold_iterations,
                                     score.evaluations);
    if (!r) {
      score.failure = "the model fitted on fold " + std::to_string(f + 1) + " cannot predict its held-out rows";
      return score;
    }
    for (std::size_t k = 0; k < folds.held_out[f].size(); ++k) {
      score.held_out_residual.row(static_cast<Eigen::Index>(folds.held_out[f][k])) = r->row(static_cast<Eigen::Index>(k));
    }
  }
  score_held_out(score, base_residual, folds);
  return score;
}

std::size_t fitted_parameter_count(const CandidateScore& score) {
  if (!score.fit) return 0;
  return static_cast<std::size_t>(std::count_if(score.fit->parameters.begin(), score.fit->parameters.end(),
                                                [](const ParameterEstimate& p) { return !p.held; }));
}

void score_held_out(CandidateScore& score, const Eigen::MatrixX2d& base_residual, const Folds& folds) {
  score.held_out_rmse_nm = std::sqrt(pooled_mean_square(score.held_out_residual));
  const double base_rmse = std::sqrt(pooled_mean_square(base_residual));
  score.reduction = base_rmse > 0.0 ? 1.0 - score.held_out_rmse_nm / base_rmse : 0.0;
  score.against_base = paired_block_test(base_residual, score.held_out_residual, folds.block_of, folds.blocks, false);
}

}  // namespace gc
