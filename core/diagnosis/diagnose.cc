#include "core/diagnosis/diagnose.h"

#include <algorithm>
#include <cmath>

#include "core/diagnosis/model_residuals.h"
#include "core/diagnosis/noise_estimate.h"
#include "core/diagnosis/verdict_text.h"
#include "core/effects/effect_registry.h"
#include "core/model_error.h"

namespace gc {
namespace {

std::vector<std::size_t> time_ordered(std::span<const RecordedSample> observations) {
  std::vector<std::size_t> rows = all_rows(observations.size());
  std::stable_sort(rows.begin(), rows.end(), [&](std::size_t a, std::size_t b) {
    return observations[a].input.time_s < observations[b].input.time_s;
  });
  return rows;
}

/// At most `count` rows evenly spaced through `rows` (which are in time order).
std::vector<std::size_t> evenly_spaced(const std::vector<std::size_t>& rows, std::size_t count) {
  if (rows.size() <= count) return rows;
  std::vector<std::size_t> out;
  for (std::size_t k = 0; k < count; ++k) out.push_back(rows[k * rows.size() / count]);
  return out;
}

Eigen::MatrixX2d select_rows(const Eigen::MatrixX2d& residual, const std::vector<std::size_t>& all,
                             const std::vector<std::size_t>& subset) {
  Eigen::MatrixX2d out(static_cast<Eigen::Index>(subset.size()), 2);
  std::size_t k = 0;
  for (std::size_t i = 0; i < all.size() && k < subset.size(); ++i) {
    if (all[i] == subset[k]) out.row(static_cast<Eigen::Index>(k++)) = residual.row(static_cast<Eigen::Index>(i));
  }
  return out;
}

/// Cosine of the angle between two candidates' corrections to the base model (uncentred, so
/// two constant offsets count as alike).
double correction_similarity(const Eigen::MatrixX2d& base, const Eigen::MatrixX2d& a, const Eigen::MatrixX2d& b) {
  const Eigen::MatrixX2d ca = base - a, cb = base - b;
  const double denominator = ca.norm() * cb.norm();
  return denominator > 0.0 ? (ca.array() * cb.array()).sum() / denominator : 0.0;
}

std::vector<CandidateScore> rank_candidates(const CouplingModel& model, std::span<const RecordedSample> observations,
                                            const std::vector<std::size_t>& search, const Eigen::MatrixX2d& base,
                                            const Folds& folds, const ParallelFor& parallel,
                                            const DiagnosisSettings& settings) {
  std::vector<CandidateScore> ranking;
  for (const EffectRegistration& registration : settings.library) {
    if (model.has_effect(registration.info->name)) continue;
    ranking.push_back(score_candidate(model, registration, observations, search, base, folds, parallel,
                                      settings.cross_validation));
  }
  std::stable_sort(ranking.begin(), ranking.end(), [](const CandidateScore& a, const CandidateScore& b) {
    if (a.failure.empty() != b.failure.empty()) return a.failure.empty();
    return a.held_out_rmse_nm < b.held_out_rmse_nm;
  });
  return ranking;
}

/// Significant on held-out blocks and removing a real share of the excess over the noise.
bool claimable(const CandidateScore& c, double base_ms, double noise_ms, const DiagnosisSettings& settings) {
  if (!c.failure.empty() || c.against_base.t < settings.claim_t) return false;
  const double effect_ms = c.held_out_rmse_nm * c.held_out_rmse_nm;
  const double excess = std::max(base_ms - noise_ms, 0.0);
  return base_ms - effect_ms >= settings.claim_excess_share * excess && base_ms > effect_ms;
}

std::vector<AlikeEffect> alike_effects(const CouplingModel& model, const std::vector<CandidateScore>& ranking,
                                       const Eigen::MatrixX2d& base, const Folds& folds, double base_ms,
                                       double noise_ms, std::span<const RecordedSample> observations,
                                       const std::vector<std::size_t>& rows, double noise_sigma,
                                       const DiagnosisSettings& settings) {
  std::vector<AlikeEffect> alike;
  const CandidateScore& best = ranking.front();
  for (std::size_t k = 1; k < ranking.size(); ++k) {
    const CandidateScore& other = ranking[k];
    if (!claimable(other, base_ms, noise_ms, settings)) continue;
    const double similarity = correction_similarity(base, best.held_out_residual, other.held_out_residual);
    const PairedBlockTest t = paired_block_test(other.held_out_residual, best.held_out_residual, folds.block_of, folds.blocks);
    if (similarity < settings.alike_correlation || t.t >= settings.alike_t) continue;
    alike.push_back({other.info->name, similarity, t,
                     separating_experiment(model.with_effect(best.fit->effect), model.with_effect(other.fit->effect),
                                           observations, rows, noise_sigma)});
  }
  return alike;
}

/// Per channel, the share of the base mean square that the candidate's held-out residual removes.
Eigen::Vector2d channel_reduction(const Eigen::MatrixX2d& base, const Eigen::MatrixX2d& held_out) {
  const Eigen::Array2d b = base.colwise().squaredNorm().transpose().array();
  const Eigen::Array2d h = held_out.colwise().squaredNorm().transpose().array();
  return (b > 0.0).select(1.0 - h / b.max(1e-300), 0.0).matrix();
}

/// One round: residual, noise, signature, ranking, outcome.
/// `residual`: the model's on `rows`.
DiagnosisRound search_round(const CouplingModel& model, const Eigen::MatrixX2d& residual,
                            std::span<const RecordedSample> observations, const std::vector<std::size_t>& rows,
                            const std::vector<std::size_t>& search, const Folds& folds,
                            const ParallelFor& parallel, const DiagnosisSettings& settings) {
  DiagnosisRound round;
  for (const auto& e : model.effects()) round.model_effects.push_back(e->name());
  round.noise_sigma_nm = successive_difference_noise(residual);
  const double noise_ms = round.noise_sigma_nm.squaredNorm() / 2.0;
  const double all_ms = pooled_mean_square(residual);
  round.noise_rmse_nm = std::sqrt(noise_ms);
  round.rmse_nm = std::sqrt(all_ms);
  round.signature = residual_signature(observations, rows, residual);
  // Excess over the noise beyond 3.7 standard errors of a mean square of 2n Gaussian values
  // (sqrt(2 / 2n)) and of the median-based noise estimate (about sqrt(5.4 / n)).
  const double n = static_cast<double>(rows.size());
  round.systematic = all_ms > noise_ms * (1.0 + 3.7 * std::sqrt(1.0 / n + 5.4 / n)) || round.signature.systematic();
  const Eigen::MatrixX2d base = select_rows(residual, rows, search);
  const double base_ms = pooled_mean_square(base);
  round.search_base_rmse_nm = std::sqrt(base_ms);
  if (!round.systematic) {
    round.outcome = RoundOutcome::noise;
    return round;
  }
  round.ranking = rank_candidates(model, observations, search, base, folds, parallel, settings);
  if (round.ranking.empty() || !claimable(round.ranking.front(), base_ms, noise_ms, settings)) {
    round.outcome = RoundOutcome::unexplained;
    return round;
  }
  round.alike = alike_effects(model, round.ranking, base, folds, base_ms, noise_ms, observations, rows,
                              round.noise_rmse_nm, settings);
  round.outcome = round.alike.empty() ? RoundOutcome::effect_found : RoundOutcome::indistinguishable;
  round.channel_reduction = channel_reduction(base, round.ranking.front().held_out_residual);
  return round;
}

const EffectRegistration& registration_of(const std::string& name, const DiagnosisSettings& settings) {
  for (const EffectRegistration& r : settings.library) if (r.info->name == name) return r;
  throw InvalidInput("effects." + name, "not registered");
}

}  // namespace

Diagnosis diagnose(const CouplingModel& model, std::span<const RecordedSample> observations,
                   const ParallelFor& parallel, const DiagnosisSettings& settings) {
  Diagnosis out;
  out.rows = observations.size();
  // A NaN would poison every fit silently: refuse it here, naming the row.
  for (std::size_t i = 0; i < observations.size(); ++i) {
    require_finite("recording.rows[" + std::to_string(i) + "].msy_nm", observations[i].measured.y_nm);
    require_finite("recording.rows[" + std::to_string(i) + "].msz_nm", observations[i].measured.z_nm);
  }
  const std::vector<std::size_t> ordered = time_ordered(observations);
  const ModelResiduals first = model_residuals(model, observations, ordered, parallel);
  out.excluded_rows = first.failed_rows;
  out.exclusion_reason = first.first_failure;
  std::vector<std::size_t> rows = ordered;
  std::erase_if(rows, [&](std::size_t r) { return std::binary_search(first.failed_rows.begin(), first.failed_rows.end(), r); });
  // Each round's residual on the usable rows: the first from this pass, later ones from the refit.
  Eigen::MatrixX2d residual = first.failed_rows.empty() ? first.residual : select_rows(first.residual, ordered, rows);
  const int minimum = 4 * settings.cross_validation.folds * settings.cross_validation.blocks_per_fold;
  if (rows.size() < static_cast<std::size_t>(minimum)) {
    throw InvalidInput("recording.rows", static_cast<double>(rows.size()),
                       "at least " + std::to_string(minimum) + " rows the model can predict");
  }
  const std::vector<std::size_t> search = evenly_spaced(rows, settings.search_rows);
  out.search_rows = search.size();
  const std::vector<std::size_t> refit = evenly_spaced(rows, settings.refit_rows);
  out.refit_rows = refit.size();
  const Folds folds = blocked_folds(search.size(), settings.cross_validation.folds,
                                    settings.cross_validation.blocks_per_fold);
  CouplingModel current = model;
  for (int r = 0; r < settings.max_rounds; ++r) {
    DiagnosisRound round = search_round(current, residual, observations, rows, search, folds, parallel, settings);
    if (round.outcome == RoundOutcome::effect_found || round.outcome == RoundOutcome::indistinguishable) {
      const CandidateScore& best = round.ranking.front();
      const EffectRegistration& registration = registration_of(best.info->name, settings);
      round.claimed = refit_effect(current, registration, *best.fit, observations, refit, parallel,
                                   settings.final_iterations, true);
    }
    std::optional<ModelResiduals> next;
    if (round.claimed) {
      next = model_residuals(current.with_effect(round.claimed->effect), observations, rows, parallel);
      if (!next->failed_rows.empty()) round.claimed.reset();
    }
    // A claimed effect whose refit cannot predict every row is reported with its search fit,
    // and the search stops there rather than lose rows.
    const bool continues = round.claimed.has_value();
    if (!continues && round.ranking.size() > 0 && round.outcome != RoundOutcome::noise &&
        round.outcome != RoundOutcome::unexplained) {
      round.claimed = round.ranking.front().fit;
    }
    round.verdict = round_verdict(static_cast<int>(out.rounds.size()) + 1, round);
    out.summary += (out.summary.empty() ? "" : "\n") + round.verdict;
    if (continues) {
      residual = next->residual;
      out.added.push_back(round.claimed->effect);
      current = current.with_effect(round.claimed->effect);
    }
    out.rounds.push_back(std::move(round));
    if (!continues) break;
  }
  return out;
}

}  // namespace gc
