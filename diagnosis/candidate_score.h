// One library effect as a candidate explanation of a residual: fitted on the training folds,
// scored on the held-out folds (k-fold cross-validation), so that extra parameters cannot win
// by fitting noise.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>

#include <Eigen/Dense>

#include "diagnosis/cross_validation_folds.h"
#include "diagnosis/effect_fit.h"
#include "diagnosis/paired_block_test.h"

namespace gc {

enum class CandidateKind {
  addition,    ///< a library effect the model lacks
  refinement,  ///< an effect the model has, with every parameter freed
  formula,     ///< a formula of catalogue terms (diagnosis/formula_search.h)
};

struct CandidateScore {
  CandidateKind kind = CandidateKind::addition;
  const EffectInfo* info = nullptr;
  std::optional<EffectFit> fit;   ///< on all search rows (for the ranking's parameters)
  /// Per search row, the residual of the model fitted without that row's fold [N·m].
  Eigen::MatrixX2d held_out_residual;
  double held_out_rmse_nm = 0.0;  ///< pooled over both channels
  double reduction = 0.0;         ///< 1 - held-out RMSE / the base model's RMSE on the same rows
  PairedBlockTest against_base;   ///< t > 0: better than the base model on held-out blocks
  std::string failure;            ///< non-empty when the effect could not be fitted or scored
  /// Earlier claims this candidate takes out of the model: a joint refit that puts a simpler effect
  /// of the model in the place of one (partly_claims.h, rival_of_claim).
  std::vector<std::string> replaces;
  int evaluations = 0;            ///< model evaluations of all rows it cost
  /// The family-wise p-value that noise with the residual's spectrum is explained as well
  /// (surrogate_claims.h); set for the candidates the claim rule tested that way.
  std::optional<double> surrogate_p;
};

struct CrossValidationSettings {
  int folds = 5;
  int blocks_per_fold = 20;  ///< 100 blocks of 15 search rows: enough for the paired test
  int fold_iterations = 3;  ///< Levenberg-Marquardt steps per fold, warm-started from the full fit
  FitSettings fit;
  std::uint64_t fold_seed = 0;  ///< blocked_folds' seed
};

/// The parameters its fit determined (a held one says nothing of the data); 0 unfitted.
std::size_t fitted_parameter_count(const CandidateScore& score);

/// Fills the score's held-out RMSE, reduction and paired test from its held_out_residual, against
/// the base model's residual on the same rows.
void score_held_out(CandidateScore& score, const Eigen::MatrixX2d& base_residual, const Folds& folds);

/// `rows` in time order; `base_residual` the base model's residual on them (no parameters fitted,
/// so it is its own held-out residual). `current`: the effect of this name the base model has (a
/// refinement starts from it and searches a box that holds it); nullptr for an addition.
CandidateScore score_candidate(const CouplingModel& base, const EffectRegistration& registration,
                               std::span<const RecordedSample> observations, std::span<const std::size_t> rows,
                               const Eigen::MatrixX2d& base_residual, const Folds& folds,
                               const ParallelFor& parallel, const CrossValidationSettings& settings,
                               const Effect* current = nullptr);

}  // namespace gc
