#include "diagnosis/claim_review.h"

#include <algorithm>
#include <optional>

#include "core/effects/expression.h"
#include "diagnosis/claimed_effects.h"
#include "diagnosis/formula_search.h"
#include "diagnosis/model_residuals.h"
#include "diagnosis/paired_block_test.h"
#include "diagnosis/search_round.h"

namespace gc {
namespace {

/// A fresh formula that takes over an earlier claim: its search-row score and its refit.
struct AbsorbingFormula {
  CandidateScore score;
  EffectFit refit;
};

/// A formula claimed this round may take over an earlier claim (an offset that took the mean of a
/// drift in round 1): the formula searched afresh on what the model leaves without that claim and
/// without its formula. When it does as well on held-out blocks as the model with both (paired t
/// below keep_t), it is returned, with its refit on the refit rows, to replace them.
std::optional<AbsorbingFormula> formula_absorbing(const CouplingModel& model, const std::string& name,
                                           const Eigen::MatrixX2d& held_out, std::span<const RecordedSample> observations,
                                           const std::vector<std::size_t>& search, const std::vector<std::size_t>& refit,
                                           const Folds& folds, const ParallelFor& parallel, const FormulaSettings& settings,
                                           double keep_t) {
  const CouplingModel bare = model.without_effect(name).without_effect(kExpressionEffect);
  const ModelResiduals on_search = model_residuals(bare, observations, search, parallel);
  if (!on_search.failed_rows.empty()) return std::nullopt;
  const std::optional<CandidateScore> fresh = formula_candidate(observations, search, on_search.residual, folds, settings);
  if (!fresh || paired_block_test(fresh->held_out_residual, held_out, folds.block_of, folds.blocks).t >= keep_t) {
    return std::nullopt;
  }
  const ModelResiduals on_refit = model_residuals(bare, observations, refit, parallel);
  if (!on_refit.failed_rows.empty()) return std::nullopt;
  std::vector<std::string> terms;
  for (const ParameterEstimate& p : fresh->fit->parameters) terms.push_back(p.name);
  std::optional<EffectFit> fitted = fit_formula(observations, refit, on_refit.residual, terms, settings.variance_inflation);
  if (!fitted) return std::nullopt;
  return AbsorbingFormula{*fresh, std::move(*fitted)};
}

}  // namespace


std::vector<std::string> redundant_claims(const CouplingModel& model, const std::vector<std::string>& earlier,
                                          const Eigen::MatrixX2d& held_out,
                                          std::span<const RecordedSample> observations,
                                          std::span<const std::size_t> rows, const Folds& folds,
                                          const ParallelFor& parallel, double keep_t) {
  std::vector<std::string> drop;
  for (const std::string& name : earlier) {
    const ModelResiduals without = model_residuals(model.without_effect(name), observations, rows, parallel);
    if (!without.failed_rows.empty()) continue;
    if (paired_block_test(without.residual, held_out, folds.block_of, folds.blocks).t < keep_t) drop.push_back(name);
  }
  return drop;
}

void revisit_claims(CouplingModel& model, DiagnosisRound& round, std::vector<std::shared_ptr<const Effect>>& added,
                    const CouplingModel& given, std::span<const RecordedSample> observations,
                    const std::vector<std::size_t>& search, const std::vector<std::size_t>& refit, const Folds& folds,
                    const ParallelFor& parallel, const DiagnosisSettings& settings) {
  std::vector<std::string> revisit;
  const std::vector<std::string> claimed = claimed_names(*round.claimed->effect);
  for (const auto& earlier : added) {
    if (!given.has_effect(earlier->name()) &&
        std::find(claimed.begin(), claimed.end(), earlier->name()) == claimed.end()) {
      revisit.push_back(earlier->name());
    }
  }
  const auto drop = [&](const std::string& name) {
    round.dropped.push_back(name);
    std::erase_if(added, [&](const auto& e) { return e->name() == name; });
  };
  for (const std::string& name : redundant_claims(model, revisit, round.chosen().held_out_residual, observations, search,
                                                  folds, parallel, settings.keep_t)) {
    model = model.without_effect(name);
    drop(name);
  }
  if (!round.formula_chosen) return;
  for (const std::string& name : revisit) {
    if (name == kExpressionEffect || std::find(round.dropped.begin(), round.dropped.end(), name) != round.dropped.end()) {
      continue;
    }
    std::optional<AbsorbingFormula> absorbed = formula_absorbing(model, name, round.chosen().held_out_residual,
                                                                 observations, search, refit, folds, parallel,
                                                                 formula_settings(round, settings), settings.keep_t);
    if (!absorbed) continue;
    const CouplingModel taken = model.without_effect(name).with_effect(absorbed->refit.effect);
    if (!model_residuals(taken, observations, refit, parallel).failed_rows.empty()) continue;
    model = taken;
    // The round's formula record becomes the one claimed, so the JSON's formula, its claimed
    // parameters and the verdict's held-out figures are of one formula. Its fall is quoted against
    // the round's model, as every candidate's.
    absorbed->score.reduction = round.search_base_rmse_nm > 0.0
                                    ? 1.0 - absorbed->score.held_out_rmse_nm / round.search_base_rmse_nm
                                    : 0.0;
    round.formula = std::move(absorbed->score);
    round.claimed = std::move(absorbed->refit);
    drop(name);
  }
}

}  // namespace gc
