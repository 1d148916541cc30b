#include "diagnosis/diagnose.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>

#include "diagnosis/row_selection.h"
#include "diagnosis/row_exclusion.h"
#include "diagnosis/test_blocks.h"
#include "diagnosis/claimed_effects.h"
#include "diagnosis/partly_claims.h"
#include "diagnosis/candidate_ranking.h"
#include "diagnosis/claim_rule.h"
#include "diagnosis/alike_candidates.h"
#include "diagnosis/claim_order.h"
#include "diagnosis/claim_carries.h"
#include "diagnosis/search_round.h"
#include "diagnosis/candidates_side_by_side.h"
#include "diagnosis/claim_review.h"
#include "diagnosis/delay_estimate.h"
#include "diagnosis/mains_pickup.h"
#include "diagnosis/model_residuals.h"
#include "diagnosis/noise_estimate.h"
#include "diagnosis/polarity_flip.h"
#include "diagnosis/signature_held_out.h"
#include "diagnosis/slow_wander.h"
#include "diagnosis/input_noise_check.h"
#include "diagnosis/surrogate_claims.h"
#include "diagnosis/verdict_text.h"
#include "diagnosis/time_step.h"
#include "diagnosis/whole_fifths.h"
#include "core/effects/effect_registry.h"
#include "core/effects/expression.h"
#include "core/effects/expression_terms.h"
#include "core/effects/joint_effect.h"
#include "core/model_error.h"

namespace gc {
namespace {

/// The round's claim refitted on the refit rows (an effect from its search fit; a formula by least
/// squares), or nullopt when the refit cannot predict those rows.
std::optional<EffectFit> refit_claim(const CouplingModel& model, const DiagnosisRound& round,
                                     std::span<const RecordedSample> observations, const std::vector<std::size_t>& rows,
                                     const Eigen::MatrixX2d& residual, const std::vector<std::size_t>& refit,
                                     const ParallelFor& parallel, const DiagnosisSettings& settings) {
  const CandidateScore& chosen = round.chosen();
  if (round.formula_chosen) {
    std::vector<std::string> terms;
    for (const ParameterEstimate& p : chosen.fit->parameters) terms.push_back(p.name);
    const std::shared_ptr<const Effect> earlier = model.effect(kExpressionEffect);
    if (!earlier) return fit_formula(observations, refit, select_rows(residual, rows, refit), terms, round.noise.variance_inflation());
    // A model with a formula already gets one formula over both sets of terms, refitted together on
    // what the model leaves without it: a second expression would replace the first.
    for (const ParameterSpec& p : earlier->info().parameters) {
      if (std::find(terms.begin(), terms.end(), p.name) == terms.end()) terms.push_back(p.name);
    }
    const ModelResiduals without = model_residuals(model.without_effect(kExpressionEffect), observations, refit, parallel);
    if (!without.failed_rows.empty()) return std::nullopt;
    return fit_formula(observations, refit, without.residual, terms, round.noise.variance_inflation());
  }
  CouplingModel base = model;
  for (const std::string& name : chosen.replaces) base = base.without_effect(name);
  const std::shared_ptr<const Effect> current = base.effect(chosen.info->name);
  const std::optional<EffectRegistration> registration =
      current ? registration_for(*current, settings) : registration_for(*chosen.fit->effect, settings);
  if (!registration) return std::nullopt;
  std::optional<EffectFit> fit =
      refit_effect(base, *registration, *chosen.fit, observations, refit, parallel, settings.final_iterations, true);
  // s^2 (J'J)^-1 counts every sample as independent; correlated noise carries fewer.
  const double inflation = std::sqrt(round.noise.variance_inflation());
  if (fit) for (ParameterEstimate& p : fit->parameters) if (p.standard_error) *p.standard_error *= inflation;
  return fit;
}

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

/// After the round's claim is in `model`: drops the earlier claims (in `added`) it makes idle, and,
/// when the claim is a formula, those a fresh formula can take over (the claim becomes that formula).
/// Refinements of the given model's effects are refined again later, never removed.
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

}  // namespace

const char* to_string(RoundOutcome outcome) {
  switch (outcome) {
    case RoundOutcome::effect_found: return "effect_found";
    case RoundOutcome::indistinguishable: return "indistinguishable";
    case RoundOutcome::noise: return "noise";
    case RoundOutcome::unexplained: return "unexplained";
    case RoundOutcome::partly_explained: return "partly_explained";
    case RoundOutcome::formula_proposed: return "formula_proposed";
  }
  return "";
}

const CandidateScore& DiagnosisRound::chosen() const { return formula_chosen ? *formula : ranking.front(); }

Diagnosis diagnose(const CouplingModel& model, std::span<const RecordedSample> observations,
                   const ParallelFor& parallel, const DiagnosisSettings& settings) {
  if (settings.formula_settings.teeth == 0) {  // the tooth-mesh orders of the model's coupling
    DiagnosisSettings own = settings;
    own.formula_settings.teeth = model.geometry().teeth();
    return diagnose(model, observations, parallel, own);
  }
  Diagnosis out;
  out.rows = observations.size();
  // A NaN would poison every fit silently: refuse it here, naming the row.
  for (std::size_t i = 0; i < observations.size(); ++i) {
    require_finite("recording.rows[" + std::to_string(i) + "].msy_nm", observations[i].measured.y_nm);
    require_finite("recording.rows[" + std::to_string(i) + "].msz_nm", observations[i].measured.z_nm);
  }
  const DataQuality quality = check_data_quality(observations, settings.data_quality);
  out.data_quality = quality.findings;
  std::vector<std::size_t> ordered = time_ordered(observations);
  std::erase_if(ordered, [&](std::size_t r) {
    return std::binary_search(quality.excluded_rows.begin(), quality.excluded_rows.end(), r);
  });
  const ModelResiduals first = model_residuals(model, observations, ordered, parallel);
  out.excluded_rows = first.failed_rows;
  out.exclusion_reason = first.first_failure;
  std::vector<std::size_t> rows = ordered;
  std::erase_if(rows, [&](std::size_t r) { return std::binary_search(first.failed_rows.begin(), first.failed_rows.end(), r); });
  // Each round's residual on the usable rows: the first from this pass, later ones from the refit.
  Eigen::MatrixX2d residual = first.failed_rows.empty() ? first.residual : select_rows(first.residual, ordered, rows);
  exclude_moment_flips(out, observations, rows, residual);
  out.outlier_rows = exclude_outliers(rows, residual, settings.outlier_deviations);
  const int minimum = 4 * settings.cross_validation.folds * settings.cross_validation.blocks_per_fold;
  if (rows.size() < static_cast<std::size_t>(minimum)) {
    throw InvalidInput("recording.rows", static_cast<double>(rows.size()),
                       "at least " + std::to_string(minimum) + " rows the model can predict");
  }
  const std::vector<std::size_t> search = evenly_spaced(rows, settings.search_rows);
  out.search_rows = search.size();
  const std::vector<std::size_t> refit = evenly_spaced(rows, settings.refit_rows);
  out.refit_rows = refit.size();
  const Folds folds = with_test_blocks(
      blocked_folds(search.size(), settings.cross_validation.folds, settings.cross_validation.blocks_per_fold,
                    settings.cross_validation.fold_seed),
      test_block_rows(estimate_noise(residual), rows.size(), search.size(), settings));
  if (auto spikes = spike_finding(out.outlier_rows, observations, settings.outlier_deviations)) {
    out.data_quality.push_back(std::move(*spikes));
  }
  out.excluded_ranges = excluded_ranges(out.data_quality, out.excluded_rows, out.exclusion_reason, observations);
  out.summary = data_quality_text(out.data_quality);
  if (!out.outlier_rows.empty()) {
    out.summary += (out.summary.empty() ? "" : "\n") + std::to_string(out.outlier_rows.size()) + " of " +
                   std::to_string(out.rows) + " samples excluded as outliers (more than " +
                   short_number(settings.outlier_deviations) + " robust deviations from the running median of their neighbours).";
  }
  CouplingModel current = model;
  std::set<std::string> partly;  // effects added by a round that said they explain only partly
  std::map<std::string, std::string> rivals;  // a partly claim's rival (rival_of_claim)
  for (int r = 0; r < settings.max_rounds; ++r) {
    DiagnosisRound round =
        search_round(current, residual, observations, rows, search, refit, folds, parallel, model, partly, rivals, settings);
    const bool claims = round.outcome != RoundOutcome::noise && round.outcome != RoundOutcome::unexplained;
    if (claims) round.claimed = refit_claim(current, round, observations, rows, residual, refit, parallel, settings);
    std::optional<ModelResiduals> next;
    CouplingModel candidate = current;
    if (round.claimed) {
      for (const std::string& name : round.chosen().replaces) candidate = candidate.without_effect(name);
      candidate = candidate.with_effect(round.claimed->effect);  // model_with_candidate, with the refit
      next = model_residuals(candidate, observations, rows, parallel);
      if (!next->failed_rows.empty()) round.claimed.reset();
    }
    // A claim whose refit cannot predict every row is reported with its search fit, and the
    // search stops there rather than lose rows.
    const bool continues = round.claimed.has_value();
    if (!continues && claims) round.claimed = round.chosen().fit;
    if (continues) {
      for (const std::string& name : round.chosen().replaces) {
        round.dropped.push_back(name);
        std::erase_if(out.added, [&](const auto& e) { return e->name() == name; });
        partly.erase(name);
        rivals.erase(name);
      }
      const CouplingModel claimed_model = candidate;
      const std::vector<std::shared_ptr<const Effect>> added_before = out.added;
      const std::optional<EffectFit> claimed_fit = round.claimed;
      const std::optional<CandidateScore> formula_before = round.formula;
      // A dense-row formula's held-out residual is not on the search rows the revisit compares.
      if (!round.formula_on_dense_rows) {
        revisit_claims(candidate, round, out.added, model, observations, search, refit, folds, parallel, settings);
      }
      if (!round.dropped.empty()) {
        // A claim dropped or taken over changed the model: its residual again, on every row. Should
        // that refuse a row (a dropped effect held it inside the jam angle), every claim stays.
        std::optional<ModelResiduals> revisited = model_residuals(candidate, observations, rows, parallel);
        if (revisited->failed_rows.empty()) {
          next = std::move(revisited);
        } else {
          candidate = claimed_model;
          out.added = added_before;
          round.claimed = claimed_fit;
          round.formula = formula_before;
          const std::vector<std::string>& replaced = round.chosen().replaces;
          std::erase_if(round.dropped, [&](const std::string& name) {
            return std::find(replaced.begin(), replaced.end(), name) == replaced.end();
          });
        }
      }
      if (const std::optional<std::string> rival = rival_of_claim(round, model)) rivals[round.chosen().info->name] = *rival;
      for (const auto& effect : claimed_effects(round.claimed->effect)) {
        partly.erase(effect->name());
        if (round.outcome == RoundOutcome::partly_explained) partly.insert(effect->name());
        std::erase_if(out.added, [&](const auto& e) { return e->name() == effect->name(); });
        out.added.push_back(effect);
      }
      residual = next->residual;
      current = candidate;
    }
    round.verdict = round_verdict(static_cast<int>(out.rounds.size()) + 1, round);
    out.summary += (out.summary.empty() ? "" : "\n") + round.verdict;
    out.rounds.push_back(std::move(round));
    if (!continues) break;
  }
  return out;
}

}  // namespace gc
