#include "diagnosis/search_round.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "diagnosis/alike_candidates.h"
#include "diagnosis/candidate_ranking.h"
#include "diagnosis/claim_carries.h"
#include "diagnosis/claim_order.h"
#include "diagnosis/claim_rule.h"
#include "diagnosis/claimed_effects.h"
#include "diagnosis/delay_estimate.h"
#include "diagnosis/input_noise_check.h"
#include "diagnosis/mains_pickup.h"
#include "diagnosis/noise_estimate.h"
#include "diagnosis/row_selection.h"
#include "diagnosis/signature_held_out.h"
#include "diagnosis/surrogate_claims.h"
#include "diagnosis/test_blocks.h"
#include "diagnosis/whole_fifths.h"

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
/// mean square of n samples with the noise's correlation, and of the noise estimate itself), a
/// channel's level 4.5 long-run standard errors from zero (level_standard_errors) and large enough
/// for an offset to pay the claim rule's least fall, or an input whose bins carry more than the
/// correlated noise allows. Without the least fall, a refitted effect's level, at most 2 % of the
/// noise, stood 6 errors out of 150,000 rows, and the round searched the library for 1.5 s to find
/// nothing.
bool is_systematic(const Eigen::MatrixX2d& residual, double noise_ms, const NoiseEstimate& noise,
                   const ResidualSignature& signature, double least_fall) {
  const double n = static_cast<double>(residual.rows());
  const double inflation = noise.variance_inflation();
  const double all_ms = pooled_mean_square(residual);
  const double level_ms = residual.colwise().mean().squaredNorm() / 2.0;  // what offsets would take
  return all_ms > noise_ms * (1.0 + 4.5 * std::sqrt(inflation / n + 5.4 * inflation / n)) ||
         (level_ms >= least_fall * all_ms && level_standard_errors(residual) > 4.5) || signature.systematic();
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

/// A formula with no more fitted parameters than the effect that predicts the held-out blocks
/// significantly better (t >= formula_over_effect_t) stands first, whatever share of its gain the
/// effect takes: the better candidate of the two and the simpler. Physics first is for a formula
/// that buys its lead with more terms (the effect's mechanism and a second one, which the next
/// round finds). Two speed terms, 2.30 kN·m held out at t = 5.5 against a gain and offset of both
/// channels (four parameters, 2.36, which took 98 % of their gain through the level and the trend
/// that moments and speed share), lost to the gain and offset, and the model kept a calibration
/// error the rig did not have (noise zoo power seed 20261253, draw 9: a speed drag). The cheap
/// conditions only; the edge must also carry to whole fifths (formula_edge_carries).
/// Fewer terms than the effect's parameters need less: two speed terms, 5.21 kN·m held out at
/// t = 2.99 against a gain and offset (5.29), lost to it, and the next round found nothing more
/// (noise zoo power seed 20261310, draw 3: a speed drag).
bool simpler_and_better(const CandidateScore& formula, const CandidateScore& effect,
                        const PairedBlockTest& formula_against_effect, const DiagnosisSettings& settings) {
  const std::size_t terms = fitted_parameter_count(formula);
  const std::size_t parameters = fitted_parameter_count(effect);
  const double least_t = terms < parameters ? settings.fewer_terms_over_effect_t : settings.formula_over_effect_t;
  return formula_against_effect.t >= least_t && terms > 0 && terms <= parameters;
}

}  // namespace

FormulaSettings formula_settings(const DiagnosisRound& round, const DiagnosisSettings& settings) {
  FormulaSettings out = settings.formula_settings;
  out.variance_inflation = round.noise.variance_inflation();
  out.time_terms = round.time_terms;
  return out;
}

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
  const Eigen::MatrixX2d on_signature_rows = select_rows(residual, rows, signature_rows);
  // The signature and the time terms side by side: each needs nothing of the other, and each has
  // stretches on one thread (a profile of a 20,000-row diagnosis: a tenth of its wall time).
  parallel(2, [&](std::size_t begin, std::size_t end) {
    for (std::size_t part = begin; part < end; ++part) {
      if (part == 0) {
        // On the refit rows (at most 20,000, evenly spaced): the partial-dependence backfits are per input.
        round.signature = residual_signature(observations, signature_rows, on_signature_rows, parallel,
                                             round.noise.variance_inflation());
      } else {
        round.time_terms = time_terms_for(observations, signature_rows, on_signature_rows, parallel);
      }
    }
  });
  // The level test is against the variogram's noise, which a cycle or a step in time does not
  // inflate: with it, a residual that no input explains is still searched for a time pattern.
  // Cycles and steps on the dense rows (on the search rows of a long recording a cycle of a few
  // seconds aliases, and a step's time is known only to their spacing). Each stands out of the
  // noise by its own test (cycle_period.h, change_point.h), and is something to explain: an
  // interference that no input shows hides from the signature, and from a variogram, which takes
  // a cycle of a few samples for correlated noise.
  round.mains_pickup =
      take_out_mains_cycles(round.time_terms, observations, signature_rows, on_signature_rows, settings.formula_settings.teeth);
  round.systematic = is_systematic(residual, round.noise.mean_square(), round.noise, round.signature, settings.claim_least_fall) ||
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
  if (const auto delay = moment_delay_estimate(observations, signature_rows, select_rows(residual, rows, signature_rows), parallel)) {
    hints.push_back({{"delay_s", *delay}});
  }
  // The formula's search needs nothing of the effects' ranking and runs on one thread: beside the
  // ranking, not after it (about 0.07 s of a 20,000-row diagnosis on one thread, in a profile).
  parallel(2, [&](std::size_t begin, std::size_t end) {
    for (std::size_t task = begin; task < end; ++task) {
      if (task == 0) {
        round.ranking = rank_candidates(model, observations, search, base, folds, parallel, given, partly, rivals, settings, hints);
      } else if (settings.formula) {
        round.formula = formula_candidate(observations, search, base, folds, formula_settings(round, settings));
      }
    }
  });
  put_claim_first(round.ranking, base_ms, noise_ms, folds, settings);
  put_simpler_swap_first(round.ranking, folds, settings);
  put_simplest_alike_first(round.ranking, base, folds, base_ms, noise_ms, settings);
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
  // Every effect, and the formula below, must add to the model fed its inputs read back from their
  // sensors' noise.
  ReadBackOnce read_back(model, observations, rows, search, parallel);
  demote_what_noisy_inputs_explain(
      round.ranking, model, read_back, search, folds, parallel, settings.cross_validation, settings.claim_t,
      [&](const CandidateScore& c) { return claimable(c, base_ms, noise_ms, settings); },
      [&](const Effect& e) { return registration_for(e, settings); });
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
  if (round.formula && !round.ranking.empty() && round.ranking.front().failure.empty()) {
    round.formula_against_effect = paired_block_test(round.ranking.front().held_out_residual,
                                                     round.formula->held_out_residual, folds.block_of, folds.blocks);
  }
  // Plausibility is advice, never a veto: an effect outside its plausible range (a rig aligned
  // worse than usual) keeps the claim unless the formula is significantly better. An effect held
  // on a physical bound, which cannot say how far beyond it the truth lies, yields to a claimable
  // formula, unless it takes most of what the formula finds (below): then it is claimed as partly
  // explaining, and the next round looks for the rest (a spacing error at the library's 100 um,
  // whose truth was 100 um with a touch-up of x1.4, lost to three torque and misalignment terms).
  const auto formula_over_effect = [&] {
    const CandidateScore& effect = round.ranking.front();
    const double effect_gain = base_ms - std::pow(effect.held_out_rmse_nm, 2);
    const double formula_gain = base_ms - std::pow(round.formula->held_out_rmse_nm, 2);
    return at_bound(effect) || (round.formula_against_effect.t >= settings.formula_over_effect_t &&
                                formula_gain >= settings.formula_over_effect_gain * effect_gain);
  };
  // Asked before the formula's read-back check and again after it (which changes at most its
  // failure): the whole-fifths refits cost an effect's scoring, so they are made once.
  std::optional<bool> simpler_once;
  const auto formula_simpler_and_better = [&] {
    if (!simpler_once) {
      const CandidateScore& effect = round.ranking.front();
      simpler_once = simpler_and_better(*round.formula, effect, round.formula_against_effect, settings) &&
                     formula_edge_carries(*round.formula, effect, model, observations, search, base, fifths, parallel,
                                          settings);
    }
    return *simpler_once;
  };
  bool formula_ok = round.formula && claimable(*round.formula, base_ms, noise_ms, settings);
  if (formula_ok && (!effect_ok || formula_over_effect() || formula_simpler_and_better())) {
    // Only where the formula could be the claim: the check may search the formula again.
    if (const std::optional<ReadBackInputs>& cleaner = read_back.get()) {
      demote_formula_that_noisy_inputs_explain(
          *round.formula, *cleaner, observations, search, folds, formula_settings(round, settings), settings.claim_t,
          [&](const CandidateScore& c) { return claimable(c, base_ms, noise_ms, settings); });
    }
    formula_ok = claimable(*round.formula, base_ms, noise_ms, settings);
  }
  if (formula_ok && effect_ok) {
    const CandidateScore& effect = round.ranking.front();
    round.formula_simpler_and_better = formula_simpler_and_better();
    round.formula_chosen = round.formula_simpler_and_better || formula_over_effect();
    if (round.formula_chosen && !round.formula_simpler_and_better &&
        effect_explains_part(effect, *round.formula, base, observations, search, folds,
                             formula_settings(round, settings))) {
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
      // It must add to the model fed its inputs read back, as on the search rows: the read-back
      // model's residual at the dense rows, less its levels as the dense residual is.
      if (std::optional<ReadBackInputs> cleaner = read_back.at(signature_rows)) {
        cleaner->residual = without_levels(cleaner->residual);
        demote_formula_that_noisy_inputs_explain(*formula, *cleaner, observations, signature_rows, dense_folds, fast,
                                                 settings.claim_t, dense_claimable);
        dense_ok = formula->failure.empty();
      }
    }
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
    if (!round.unstructured_excess) {
      // Noisy input sensors put structure in the inputs too (errors in the variables): it must pay
      // beside the model fed its inputs read back from their noise, as an effect must.
      if (const std::optional<ReadBackInputs>& cleaner = read_back.get()) {
        const std::optional<CandidateScore> beside =
            signature_held_out(observations, search, cleaner->residual, folds, round.signature);
        round.unstructured_excess =
            !beside || !claimable(*beside, pooled_mean_square(cleaner->residual), noise_ms, settings);
      }
    }
    if (!round.unstructured_excess) {
      // The third test, as an effect's: noise with the residual's own spectrum, binned by the same
      // inputs, is explained as well (a random walk on a 6 s recording, whose rotation phase and
      // temperature move with time, was "unexplained" with a 63 % fall through interleaved folds),
      // judged by the same statistics as an effect's, prewhitened where the residual is coloured.
      if (const std::optional<SurrogateDesign> design = signature_design(observations, search, round.signature)) {
        const double p = surrogate_p_values(base, {*design}, settings.surrogate_claims.level,
                                            settings.surrogate_claims.seed, 1, parallel,
                                            surrogate_filter(model, observations, search, base))
                             .front();
        round.unstructured_excess = p > settings.surrogate_claims.level;
      }
    }
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
      const ResidualSignature correction = residual_signature(observations, search, base - best.held_out_residual, parallel, inflation);
      const ResidualSignature after = residual_signature(observations, search, best.held_out_residual, parallel, inflation);
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

}  // namespace gc
