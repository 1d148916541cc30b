#include "diagnosis/diagnose.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <set>

#include "core/model_error.h"
#include "diagnosis/claim_refit.h"
#include "diagnosis/claim_review.h"
#include "diagnosis/claimed_effects.h"
#include "diagnosis/model_residuals.h"
#include "diagnosis/noise_estimate.h"
#include "diagnosis/partly_claims.h"
#include "diagnosis/programme_holds.h"
#include "diagnosis/row_exclusion.h"
#include "diagnosis/row_selection.h"
#include "diagnosis/search_round.h"
#include "diagnosis/test_blocks.h"
#include "diagnosis/verdict_text.h"

namespace gc {

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
    const SensorMoments& m = observations[i].measured;
    if (std::isfinite(m.y_nm) && std::isfinite(m.z_nm)) continue;  // the field's name only for the bad row
    require_finite("recording.rows[" + std::to_string(i) + "].msy_nm", m.y_nm);
    require_finite("recording.rows[" + std::to_string(i) + "].msz_nm", m.z_nm);
  }
  DataQuality quality = check_data_quality(observations, settings.data_quality);
  const std::vector<std::size_t> every = time_ordered(observations);
  std::optional<ModelResiduals> on_every;
  if (has_held_inputs(quality)) {
    // A held input is the programme's when the model predicts the moments there as well as elsewhere.
    on_every = model_residuals(model, observations, every, parallel);
    release_programme_holds(quality, observations, every, *on_every);
  }
  out.data_quality = quality.findings;
  std::vector<std::size_t> ordered = every;
  std::erase_if(ordered, [&](std::size_t r) {
    return std::binary_search(quality.excluded_rows.begin(), quality.excluded_rows.end(), r);
  });
  // Every row predicted once: the pass over all rows serves when it refused none (its first
  // refusal's message would otherwise be a row's that may now be excluded).
  const ModelResiduals first = on_every && on_every->failed_rows.empty()
                                   ? ModelResiduals{select_rows(on_every->residual, every, ordered), {}, {}}
                                   : model_residuals(model, observations, ordered, parallel);
  out.excluded_rows = first.failed_rows;
  out.exclusion_reason = first.first_failure;
  std::vector<std::size_t> rows = ordered;
  std::erase_if(rows, [&](std::size_t r) { return std::binary_search(first.failed_rows.begin(), first.failed_rows.end(), r); });
  // Each round's residual on the usable rows: the first from this pass, later ones from the refit.
  Eigen::MatrixX2d residual = first.failed_rows.empty() ? first.residual : select_rows(first.residual, ordered, rows);
  exclude_moment_flips(out, observations, rows, residual);
  out.outlier_rows = exclude_outliers(observations, rows, residual, settings.outlier_deviations);
  exclude_rows_at_model_jumps(out, model, observations, rows, residual, parallel);
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
  const int minimum = 4 * settings.cross_validation.folds * settings.cross_validation.blocks_per_fold;
  const std::size_t predictable = observations.size() - first.failed_rows.size();
  if (predictable < static_cast<std::size_t>(minimum)) {
    throw InvalidInput("recording.rows", static_cast<double>(predictable),
                       "at least " + std::to_string(minimum) + " rows the model can predict");
  }
  if (rows.size() < static_cast<std::size_t>(minimum)) {
    // The recording was long enough; what the data-quality stage took out of it leaves too little
    // for held-out tests. Its findings are the answer, not an error that hides them.
    out.summary += (out.summary.empty() ? "" : "\n") + std::string("No physics diagnosed: ") +
                   std::to_string(rows.size()) + " of " + std::to_string(out.rows) +
                   " rows are left after the exclusions, and held-out tests need at least " + std::to_string(minimum) + ".";
    return out;
  }
  const std::vector<std::size_t> search = evenly_spaced(rows, settings.search_rows);
  out.search_rows = search.size();
  const std::vector<std::size_t> refit = evenly_spaced(rows, settings.refit_rows);
  out.refit_rows = refit.size();
  const Folds folds = with_test_blocks(
      blocked_folds(search.size(), settings.cross_validation.folds, settings.cross_validation.blocks_per_fold,
                    settings.cross_validation.fold_seed),
      test_block_rows(estimate_noise(residual), rows.size(), search.size(), settings));
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
