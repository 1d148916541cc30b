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

/// An input that carries at least this share of an effect's correction is one the effect explains.
constexpr double kExplainedInputShare = 0.1;

/// Per channel, the share of the base mean square that the candidate's held-out residual removes.
Eigen::Vector2d channel_reduction(const Eigen::MatrixX2d& base, const Eigen::MatrixX2d& held_out) {
  const Eigen::Array2d b = base.colwise().squaredNorm().transpose().array();
  const Eigen::Array2d h = held_out.colwise().squaredNorm().transpose().array();
  return (b > 0.0).select(1.0 - h / b.max(1e-300), 0.0).matrix();
}

/// The residual is more than noise: its mean square beyond the noise's by 4.5 standard errors (of a
/// mean square of n samples with the noise's correlation, and of the noise estimate itself), or an
/// input whose bins carry more than the correlated noise allows.
bool is_systematic(double all_ms, double noise_ms, std::size_t rows, const NoiseEstimate& noise,
                   const ResidualSignature& signature) {
  const double n = static_cast<double>(rows);
  const double inflation = noise.variance_inflation();
  return all_ms > noise_ms * (1.0 + 4.5 * std::sqrt(inflation / n + 5.4 * inflation / n)) || signature.systematic();
}

FormulaSettings formula_settings(const DiagnosisRound& round, const DiagnosisSettings& settings) {
  FormulaSettings out = settings.formula_settings;
  out.variance_inflation = round.noise.variance_inflation();
  out.time_terms = round.time_terms;
  return out;
}

/// True when the formula alone does not beat the effect followed by a formula of what the effect
/// leaves (paired t < 2): the formula's advantage is that it also takes a second mechanism, which
/// the next round finds after the effect (physics first). But not when the effect is idle beside
/// that second formula: its terms fitted without the effect do as well as with it (paired t < 2).
/// Then the effect only took a slice of what those terms say (a gain and offset of both channels
/// took a fifth of a rig's travel-sign hysteresis, and stayed in the model as a wrong calibration).
bool effect_explains_part(const CandidateScore& effect, const CandidateScore& formula, const Eigen::MatrixX2d& base,
                          std::span<const RecordedSample> observations, const std::vector<std::size_t>& search,
                          const Folds& folds, const FormulaSettings& settings) {
  const std::optional<CandidateScore> rest = formula_candidate(observations, search, effect.held_out_residual, folds, settings);
  const Eigen::MatrixX2d& both = rest ? rest->held_out_residual : effect.held_out_residual;
  if (paired_block_test(both, formula.held_out_residual, folds.block_of, folds.blocks).t >= 2.0) return false;
  if (!rest) return true;
  std::vector<std::string> terms;
  for (const ParameterEstimate& p : rest->fit->parameters) terms.push_back(p.name);
  const std::optional<Eigen::MatrixX2d> without_effect = formula_held_out(observations, search, base, terms, folds);
  return !without_effect || paired_block_test(*without_effect, both, folds.block_of, folds.blocks).t >= 2.0;
}

/// Removes from `time_terms` a cycle at the mains frequency (mains_pickup.h), direct or aliased by
/// the rows' sample rate, and returns what the verdict says of it ("" when none).
std::string take_out_mains_cycles(std::vector<std::string>& time_terms, std::span<const RecordedSample> observations,
                                  const std::vector<std::size_t>& rows) {
  if (rows.size() < 2) return "";
  Eigen::VectorXd t(static_cast<Eigen::Index>(rows.size()));
  for (std::size_t k = 0; k < rows.size(); ++k) t(static_cast<Eigen::Index>(k)) = observations[rows[k]].input.time_s;
  const double step = typical_time_step(t);
  const double duration = t(t.size() - 1) - t(0);
  if (!(step > 0.0) || !(duration > 0.0)) return "";
  std::string text;
  std::erase_if(time_terms, [&](const std::string& name) {
    const ExpressionTerm* term = find_expression_term(name);
    if (!term || !(term->period_s > 0.0)) return false;
    const double f = 1.0 / term->period_s;
    // Only mains that the rows resolve: aliased, 60 Hz at 50 Hz sampling lands at 10 Hz, where a
    // 56-tooth mesh at 10.7 rpm also is.
    const std::optional<double> mains = mains_frequency(f, 1.0 / step, 1.0 / duration);
    if (mains && *mains >= 0.5 / step) return false;
    if (mains && text.empty()) text = mains_pickup_text(f, *mains);
    return mains.has_value();
  });
  return text;
}

/// One round: residual, noise, signature, candidates, outcome.
/// `residual`: the model's on `rows`.
DiagnosisRound search_round(const CouplingModel& model, const Eigen::MatrixX2d& residual,
                            std::span<const RecordedSample> observations, const std::vector<std::size_t>& rows,
                            const std::vector<std::size_t>& search, const std::vector<std::size_t>& signature_rows,
                            const Folds& folds, const ParallelFor& parallel, const CouplingModel& given,
                            const std::set<std::string>& partly, const std::map<std::string, std::string>& rivals,
                            const DiagnosisSettings& settings) {
  DiagnosisRound round;
  for (const auto& e : model.effects()) round.model_effects.push_back(e->name());
  round.noise = estimate_noise(residual);
  const double all_ms = pooled_mean_square(residual);
  round.rmse_nm = std::sqrt(all_ms);
  // On the refit rows (at most 20,000, evenly spaced): the partial-dependence backfits are per input.
  round.signature = residual_signature(observations, signature_rows, select_rows(residual, rows, signature_rows),
                                       round.noise.variance_inflation());
  // The level test is against the variogram's noise, which a cycle or a step in time does not
  // inflate: with it, a residual that no input explains is still searched for a time pattern.
  // Cycles and steps on the dense rows (on the search rows of a long recording a cycle of a few
  // seconds aliases, and a step's time is known only to their spacing). Each stands out of the
  // noise by its own test (cycle_period.h, change_point.h), and is something to explain: an
  // interference that no input shows hides from the signature, and from a variogram, which takes
  // a cycle of a few samples for correlated noise.
  round.time_terms = time_terms_for(observations, signature_rows, select_rows(residual, rows, signature_rows));
  round.mains_pickup = take_out_mains_cycles(round.time_terms, observations, signature_rows);
  round.systematic = is_systematic(all_ms, round.noise.mean_square(), rows.size(), round.noise, round.signature) ||
                     !round.time_terms.empty();
  // Where no input shows structure, the residual's own scale, correlation and tails are the noise's
  // unless a time pattern or a frequency is found (noise_estimate.h): the share of the excess a
  // claim must remove is then measured against heavy-tailed, long-correlated noise as it is.
  const std::optional<NoiseEstimate> as_noise =
      round.signature.systematic() ? std::nullopt : std::optional(estimate_noise(residual, true));
  // Tails included: a Student-t noise's mean square is twice its robust sigma^2 and is no physics.
  const double noise_ms = (as_noise ? *as_noise : round.noise).mean_square();
  const Eigen::MatrixX2d base = select_rows(residual, rows, search);
  const double base_ms = pooled_mean_square(base);
  round.search_base_rmse_nm = std::sqrt(base_ms);
  if (!round.systematic) {
    if (as_noise) round.noise = *as_noise;
    round.outcome = RoundOutcome::noise;
    return round;
  }
  // A skew of the moment channels, by cross-correlation on the dense rows: a start for moment_delay.
  std::vector<ParameterValues> hints;
  if (const auto delay = moment_delay_estimate(observations, signature_rows, select_rows(residual, rows, signature_rows))) {
    hints.push_back({{"delay_s", *delay}});
  }
  round.ranking = rank_candidates(model, observations, search, base, folds, parallel, given, partly, rivals, settings, hints);
  put_claim_first(round.ranking, base_ms, noise_ms, folds, settings);
  put_simpler_swap_first(round.ranking, folds, settings);
  put_simplest_alike_first(round.ranking, base, folds, base_ms, noise_ms, settings);
  if (settings.formula) round.formula = formula_candidate(observations, search, base, folds, formula_settings(round, settings));
  // The second held-out test of the claim rule: whole fifths (whole_fifths.h).
  const Folds fifths = whole_fifths(search.size(), test_rows_per_block(folds));
  demote_what_does_not_carry(round.ranking, model, observations, search, base, fifths, parallel, base_ms, noise_ms,
                             settings);
  if (round.formula && claimable(*round.formula, base_ms, noise_ms, settings) &&
      !formula_carries(*round.formula, observations, search, base, fifths)) {
    round.formula->failure = "does not carry to a fifth of the recording it was not fitted on";
  }
  // A timing effect must beat the centred average of the inputs it could be (input_noise_check.h).
  demote_what_input_noise_explains(
      round.ranking, model, observations, search, base, folds, parallel, settings.cross_validation, settings.claim_t,
      [&](const CandidateScore& c) { return claimable(c, base_ms, noise_ms, settings); });
  // The third: noise with the residual's own spectrum explains it as well (surrogate_claims.h).
  demote_what_noise_explains(
      round.ranking, round.formula, round.time_terms, model, observations, search, base, parallel,
      [&](const CandidateScore& c) { return claimable(c, base_ms, noise_ms, settings); },
      [&](const Effect& e) { return registration_for(e, settings); }, settings.surrogate_claims);
  // Refitting an effect an earlier round added and said explains only partly makes no new claim:
  // it needs to be significant, not to remove a share of the excess (a thermal misalignment fitted
  // beside a weight offset, refitted once the offset is in, took 24 % of the excess and was left
  // wrong).
  const auto refits_a_partly_claim = [&partly](const CandidateScore& c) {
    if (c.kind != CandidateKind::refinement || !c.fit || !c.fit->effect) return false;
    const std::vector<std::string> names = claimed_names(*c.fit->effect);
    return std::any_of(names.begin(), names.end(), [&partly](const std::string& n) { return partly.count(n) > 0; });
  };
  const bool refits_partly = !round.ranking.empty() && refits_a_partly_claim(round.ranking.front()) &&
                             round.ranking.front().failure.empty() &&
                             round.ranking.front().against_base.t >= settings.claim_t &&
                             std::pow(round.ranking.front().held_out_rmse_nm, 2) < base_ms;
  const bool effect_ok =
      !round.ranking.empty() && (refits_partly || claimable(round.ranking.front(), base_ms, noise_ms, settings));
  const bool formula_ok = round.formula && claimable(*round.formula, base_ms, noise_ms, settings);
  if (round.formula && !round.ranking.empty() && round.ranking.front().failure.empty()) {
    round.formula_against_effect = paired_block_test(round.ranking.front().held_out_residual,
                                                     round.formula->held_out_residual, folds.block_of, folds.blocks);
  }
  if (formula_ok && effect_ok) {
    const CandidateScore& effect = round.ranking.front();
    const PairedBlockTest t = round.formula_against_effect;
    const double effect_gain = base_ms - std::pow(effect.held_out_rmse_nm, 2);
    const double formula_gain = base_ms - std::pow(round.formula->held_out_rmse_nm, 2);
    // Plausibility is advice, never a veto: an effect outside its plausible range (a rig aligned
    // worse than usual) keeps the claim unless the formula is significantly better. Only an effect
    // held on a physical bound, which cannot say how far beyond it the truth lies, yields to it.
    round.formula_chosen = at_bound(effect) || (t.t >= settings.formula_over_effect_t &&
                                                formula_gain >= settings.formula_over_effect_gain * effect_gain);
    if (round.formula_chosen && !at_bound(effect) && effect_explains_part(effect, *round.formula, base, observations, search,
                                                                            folds, formula_settings(round, settings))) {
      round.formula_chosen = false;
    }
  } else {
    round.formula_chosen = formula_ok;
  }
  if (!effect_ok && !formula_ok && signature_rows.size() >= 2 * search.size()) {
    // A long recording: a weak formula that its 20,000 dense rows reveal, and 1,500 search rows do
    // not (a ripple of a third of the noise), is searched for on the dense rows, with folds of its
    // own. Formulas only: they are linear, so the dense rows cost milliseconds where every effect's
    // fit would cost seconds.
    const Folds dense_folds = with_test_blocks(
        blocked_folds(signature_rows.size(), settings.cross_validation.folds, settings.cross_validation.blocks_per_fold,
                      settings.cross_validation.fold_seed),
        test_block_rows(round.noise, rows.size(), signature_rows.size(), settings));
    const Eigen::MatrixX2d dense = without_levels(select_rows(residual, rows, signature_rows));
    FormulaSettings fast = formula_settings(round, settings);
    fast.fast_terms_only = true;
    std::optional<CandidateScore> formula = formula_candidate(observations, signature_rows, dense, dense_folds, fast);
    // The excess it must remove a share of is over the noise it leaves, taken at its own scale,
    // correlation and tails: on a long recording of coloured, wandering noise the variogram's
    // estimate leaves an excess that is the noise's own slow power, and a ripple of 0.3 sigma that
    // the rows reveal beyond doubt (t >= 3.5) could never remove 30 % of it. Fast terms only: no
    // term in time or temperature is offered here to follow a drift.
    const double left_ms = formula ? estimate_noise(formula->held_out_residual, true).mean_square() : noise_ms;
    const auto dense_claimable = [&](const CandidateScore& c) {
      return claimable(c, pooled_mean_square(dense), std::max(noise_ms, left_ms), settings);
    };
    bool dense_ok = formula && dense_claimable(*formula) &&
                    formula_carries(*formula, observations, signature_rows, dense,
                                    whole_fifths(signature_rows.size(), test_rows_per_block(dense_folds)));
    if (dense_ok) {
      // The same third test as on the search rows, in the same family: every candidate of the
      // round was tried before this one.
      std::vector<CandidateScore> none;
      demote_what_noise_explains(
          none, formula, round.time_terms, model, observations, signature_rows, dense, parallel, dense_claimable,
          [&](const Effect& e) { return registration_for(e, settings); }, settings.surrogate_claims,
          round.ranking.size() + (round.formula ? 1 : 0));
      dense_ok = formula->failure.empty();
    }
    if (dense_ok) {
      round.formula = std::move(formula);
      round.formula_chosen = true;
      round.formula_on_dense_rows = true;
      round.search_base_rmse_nm = std::sqrt(pooled_mean_square(dense));
      round.outcome = RoundOutcome::formula_proposed;
      round.channel_reduction = channel_reduction(dense, round.formula->held_out_residual);
      return round;
    }
  }
  if (!effect_ok && !formula_ok) {
    // Structure must be explained by something: an input (the signature), a time pattern or a
    // frequency (the formula's terms). A level above the noise estimate that none of them explains
    // on held-out data is heavy-tailed or wandering noise, not physics. The signature's structure
    // too must pay held out, by the claim rule, before it is called "unexplained".
    const std::optional<CandidateScore> held_signature =
        signature_held_out(observations, search, base, folds, round.signature);
    if (held_signature) round.signature_reduction = held_signature->reduction;
    const std::optional<CandidateScore> signature_on_fifths =
        held_signature ? signature_held_out(observations, search, base, fifths, round.signature) : std::nullopt;
    round.unstructured_excess = !held_signature || !claimable(*held_signature, base_ms, noise_ms, settings) ||
                                !signature_on_fifths ||
                                !carries_to_whole_fifths(base, signature_on_fifths->held_out_residual, fifths);
    if (round.unstructured_excess) {
      round.systematic = false;
      round.noise = estimate_noise(residual, true);
    }
    round.outcome = round.unstructured_excess ? RoundOutcome::noise : RoundOutcome::unexplained;
    return round;
  }
  if (round.formula_chosen) {
    round.outcome = RoundOutcome::formula_proposed;
  } else {
    round.alike = alike_effects(model, round.ranking, base, folds, base_ms, noise_ms, observations, rows,
                                round.noise.pooled_sigma_nm(), settings);
    round.outcome = at_bound(round.ranking.front()) ? RoundOutcome::partly_explained
                    : round.alike.empty()           ? RoundOutcome::effect_found
                                                    : RoundOutcome::indistinguishable;
    if (round.outcome == RoundOutcome::partly_explained) {
      round.partly_reason = "a fitted value on a physical bound of the effect: the truth may lie beyond what it can say, "
                            "or another mechanism has a similar signature";
    } else if (round.outcome == RoundOutcome::effect_found) {
      // Found only when what it leaves shows no structure in the inputs it explains: the physical
      // inputs that carry a real share of its correction (given the others), e.g. loading_direction
      // for hysteresis. Not time: a sweep moves every input with time, and effects act through the
      // others. A gain of both channels that took a torque sensor's nonlinearity leaves torque
      // structure behind, and is then only "partly".
      const CandidateScore& best = round.ranking.front();
      const double inflation = round.noise.variance_inflation();
      const ResidualSignature correction = residual_signature(observations, search, base - best.held_out_residual, inflation);
      const ResidualSignature after = residual_signature(observations, search, best.held_out_residual, inflation);
      for (const InputSignature& s : correction.inputs) {
        if (s.input == "time" || s.explained_share < kExplainedInputShare) continue;
        const InputSignature* left = after.find(s.input);
        if (!left || !left->systematic) continue;
        round.outcome = RoundOutcome::partly_explained;
        round.partly_reason = "the residual it leaves is still systematic against " + s.input + ", an input it explains";
        break;
      }
    }
  }
  round.channel_reduction = channel_reduction(base, round.chosen().held_out_residual);
  return round;
}

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
