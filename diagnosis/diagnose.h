// What the model lacks (docs/diagnosis.md). For a recording and a base model, each round scores
// three kinds of candidate on held-out folds: every registered effect the model does not have,
// every effect it has with its parameters freed (a refinement), and a sparse formula of physical
// terms (the discrepancy stage). The best is claimed only when its held-out gain is significant
// against autocorrelated noise; a formula wins over an effect only when significantly better, or
// when the effect's fit is implausible. After each claim, earlier claims that no longer earn their
// place are dropped. Says so when the residual is noise, and shows the residual's signature when
// nothing explains it.
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "core/coupling_model.h"
#include "core/effects/effect_registry.h"
#include "diagnosis/candidate_score.h"
#include "diagnosis/data_quality.h"
#include "diagnosis/formula_search.h"
#include "diagnosis/noise_estimate.h"
#include "core/recorded_sample.h"
#include "diagnosis/parallel_for.h"
#include "diagnosis/residual_signature.h"
#include "diagnosis/separating_experiment.h"
#include "diagnosis/surrogate_claims.h"

namespace gc {

struct DiagnosisSettings {
  /// The effects the search tries: the library, plus any effect a user registers here
  /// (docs/adding-an-effect.md). Effects the model already has are tried as refinements.
  std::vector<EffectRegistration> library = effect_registry();
  /// Also try the given model's own effects with their parameters freed (an effect this diagnosis
  /// added had every parameter free already).
  bool refinements = true;
  bool formula = true;      ///< the discrepancy stage
  FormulaSettings formula_settings;
  /// A formula is claimed over a claimable, plausible effect only when its held-out gain over that
  /// effect has a block-paired t of at least this, and it removes at least formula_over_effect_gain
  /// times the mean square the effect removes: physics first, unless the effect explains less than
  /// two thirds of what the formula shows is there (an offset taking the mean of a drift). An
  /// effect that takes too little to be claimed at all (a moment_delay's 1 % beside a formula's 17 %)
  /// is no rival: the claim rule's least fall sets it aside.
  double formula_over_effect_t = 3.0;
  double formula_over_effect_gain = 1.5;
  /// A formula of fewer fitted terms than the effect has parameters needs a block-paired t of only
  /// this over it to stand first (search_round.cc, simpler_and_better): better and simpler.
  double fewer_terms_over_effect_t = 2.0;
  /// The data-quality stage before the physics (data_quality.h).
  DataQualitySettings data_quality;
  /// Samples more than this many robust deviations from their running median are outliers,
  /// excluded and counted (diagnosis/noise_estimate.h).
  double outlier_deviations = 7.0;
  /// The search fits every candidate on at most this many rows, evenly spaced in time; the
  /// claimed effect is then refitted on every row. 1500 rows of 2 channels pin a parameter that
  /// halves the error to a few % while keeping a search of the library to seconds.
  std::size_t search_rows = 1500;
  CrossValidationSettings cross_validation;
  /// The claimed effect is refitted, from its search fit, on at most this many rows evenly spaced
  /// in time (all of a recording up to this size), then evaluated once on every row. 20,000 rows
  /// pin the parameters far below the search's scatter; the full pass gives the next round its
  /// residual. Keeps a 100,000-row diagnosis within seconds.
  std::size_t refit_rows = 20000;
  int final_iterations = 3;     ///< Levenberg-Marquardt steps of that refit
  int max_rounds = 4;
  /// Claim: the held-out gain over the base model has a block-paired t of at least this (one-sided
  /// p about 3e-4 over 100 blocks, under 3e-3 for the whole library of about ten candidates) ...
  double claim_t = 3.5;
  /// ... and noise with the residual's own spectrum is not explained as well (surrogate_claims.h) ...
  SurrogateClaimSettings surrogate_claims;
  /// ... and removes at least this share of the residual's excess over the noise (mean squares) ...
  double claim_excess_share = 0.3;
  /// ... and at least this share of the model's held-out mean square, whatever the noise estimate
  /// says: where the residual is all noise its excess is nothing, and 30 % of nothing let claims
  /// through whose held-out RMSE fell 0-3 % (a noise zoo drawn by another hand: 25 of 40 noise-only
  /// recordings claimed). 5 % of the mean square is a fall of 2.5 % of the RMSE; an effect at SNR
  /// 1.5 takes 69 %.
  double claim_least_fall = 0.05;
  /// Alike: held-out corrections correlated at least this much, and either held-out RMSEs within
  /// alike_rmse_share of each other or the better not significantly better (paired t below
  /// alike_t). The share makes the verdict stable across fold cuts: two fits 0.3 % apart are alike
  /// whichever blocks are held out, while a t near 2 is not.
  double alike_correlation = 0.9;
  double alike_rmse_share = 0.01;
  double alike_t = 2.0;
  /// Dropping an earlier claim: the model without it is not worse on held-out blocks by a paired
  /// t of this.
  double keep_t = 2.0;
};

enum class RoundOutcome {
  effect_found,       ///< one effect (added or refined) explains the residual, with plausible values
  indistinguishable,  ///< several effects explain it equally on this data
  noise,              ///< the residual is consistent with the noise
  unexplained,        ///< systematic, and neither an effect nor a formula explains it
  partly_explained,   ///< an effect lowers the error, but with implausible values (or on a bound), or
                      ///< leaves structure in the input it explains
  formula_proposed,   ///< no effect explains it; a formula of physical terms does
};

/// "effect_found", "indistinguishable", "noise", "unexplained", "partly_explained", "formula_proposed".
const char* to_string(RoundOutcome outcome);

struct AlikeEffect {
  std::string name;
  double correlation = 0.0;       ///< of its held-out corrections with the best's
  PairedBlockTest against_best;   ///< t > 0: the best is better
  SeparatingExperiment experiment;
};

struct DiagnosisRound {
  std::vector<std::string> model_effects;  ///< the model searched from
  double rmse_nm = 0.0;                    ///< the model's pooled RMSE over all usable rows
  NoiseEstimate noise;                     ///< sigma and lag-1 autocorrelation per channel (variogram fit)
  bool systematic = false;                 ///< the residual is more than noise
  /// Noise although its level is above the noise estimate: no input, time pattern or frequency
  /// explains any of it on held-out data (heavy-tailed or wandering noise).
  bool unstructured_excess = false;
  ResidualSignature signature;             ///< of the model's residual, all usable rows
  /// The signature's additive model of its systematic inputs, held out (signature_held_out.h): what
  /// an "unexplained" verdict rests on. 1 - held-out RMSE / the model's on the search rows.
  std::optional<double> signature_reduction;
  std::vector<CandidateScore> ranking;     ///< by held-out RMSE, best first; failures last
  double search_base_rmse_nm = 0.0;        ///< the model's RMSE on the search rows
  RoundOutcome outcome = RoundOutcome::noise;
  std::optional<EffectFit> claimed;        ///< refitted on the refit rows, with uncertainties
  /// Per channel, the share of the model's mean square residual the claimed effect removes (held out).
  Eigen::Vector2d channel_reduction = Eigen::Vector2d::Zero();
  std::vector<AlikeEffect> alike;          ///< when indistinguishable
  std::optional<CandidateScore> formula;   ///< the discrepancy stage's candidate, when it kept terms
  /// The formula's held-out gain over the best effect, block-paired (t > 0: the formula is better).
  PairedBlockTest formula_against_effect;
  /// The candidate claimed: ranking.front(), or the formula (then ranking.front() is the best effect).
  const CandidateScore& chosen() const;
  bool formula_chosen = false;
  /// The formula was chosen over a claimable effect for doing better with no more fitted parameters
  /// (search_round.cc, simpler_and_better): the verdict says so.
  bool formula_simpler_and_better = false;
  /// The formula was found and scored on the dense (refit) rows, with folds of their own: a weak
  /// one that the search rows of a long recording cannot show. Its held-out residual is on those rows.
  bool formula_on_dense_rows = false;
  std::vector<std::string> dropped;        ///< earlier claims dropped after this round's claim
  /// Why a claimed effect only partly explains: a value outside its plausible range, or the
  /// residual left after it still systematic against the input it explains.
  std::string partly_reason;
  std::string verdict;                     ///< plain language
  /// The time_cycle and step terms the formula stage is offered this round, found on the refit rows.
  std::vector<std::string> time_terms;
  /// A cycle at the mains frequency found and not offered (mains_pickup.h): what the verdict says.
  std::string mains_pickup;
};

struct Diagnosis {
  std::vector<DiagnosisRound> rounds;
  /// The effects the diagnosis added, in order, with their fitted values.
  std::vector<std::shared_ptr<const Effect>> added;
  std::size_t rows = 0;                   ///< rows in the recording
  std::vector<std::size_t> excluded_rows; ///< rows the base model cannot predict
  std::string exclusion_reason;           ///< the model's message for the first of them
  std::vector<std::size_t> outlier_rows;  ///< rows excluded as outliers (spikes)
  /// Instrument artefacts found before the physics (data_quality.h), spikes last; the physics is
  /// diagnosed on the rows none of them excludes.
  std::vector<DataQualityFinding> data_quality;
  /// Every row left out (artefacts, refusals, spikes) as stretches with their reason.
  std::vector<ExcludedRange> excluded_ranges;
  std::size_t search_rows = 0;
  std::size_t refit_rows = 0;
  std::string summary;                    ///< the verdicts, one line per round
};

/// Throws InvalidInput naming "recording.rows[i].msy_nm" (or msz_nm) for a non-finite measured
/// moment, and "recording.rows" when fewer than 4 * folds * blocks_per_fold rows are usable.
Diagnosis diagnose(const CouplingModel& model, std::span<const RecordedSample> observations,
                   const ParallelFor& parallel = serial_for(), const DiagnosisSettings& settings = {});

}  // namespace gc
