// The discrepancy stage: when no effect of the library explains the residual, a formula may
// (Kennedy and O'Hagan's model discrepancy, in a parametric form). The residual is regressed on the
// catalogue of physical terms (core/effects/expression_terms.h) by forward selection (orthogonal
// matching pursuit) on normalised columns: one term at a time, the one that explains most of what
// the others leave. The number of terms is chosen by the blocked cross-validation of the diagnosis
// (each fold selects on its own training rows) with the one-standard-error rule (the fewest terms
// within one standard error of the best). The terms are ordered twice: on the whole residual, and
// on what varies within each channel with the channels' constants as intercepts of every fit,
// which a run's level (its zero drift's as much as anything physical) cannot sway; the second is
// taken when it explains more of that variation on held-out rows, and keeps an intercept only
// where the level stands out of the run's wander. Forward selection rather than thresholded least squares
// (SINDy's STLSQ): the catalogue writes one mechanism in several frames that correlate on a
// recording of a few directions, and thresholding kept combinations of them where one term did.
// Beside the catalogue, the time_cycle terms of the residual's dominant period
// (diagnosis/cycle_period.h) and the step terms of its strongest change in mean
// (diagnosis/change_point.h) are offered. The chosen terms are then scored like any candidate:
// refitted on each fold's training rows, their held-out residual tested against the base model's.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "diagnosis/candidate_score.h"
#include "core/recorded_sample.h"
#include "diagnosis/parallel_for.h"

namespace gc {

struct FormulaSettings {
  int max_terms = 6;          ///< a formula a reader can take in
  /// Variance inflation of the noise's autocorrelation (NoiseEstimate::variance_inflation) for the
  /// coefficients' standard errors.
  double variance_inflation = 1.0;
  /// Terms in time offered beside the catalogue: the time_cycle terms of the residual's dominant
  /// period (cycle_period.h) and the step terms of its strongest change (change_point.h), found on
  /// rows dense enough to see them (time_terms_for). Unset: found on the rows the formula is
  /// searched on.
  std::optional<std::vector<std::string>> time_terms;
  /// The coupling's tooth count N (CouplingDefinition::teeth): the tooth-mesh order N and its
  /// sidebands N +- 1, N +- 2 are offered beside the catalogue (mesh_term_names), on rows whose
  /// Nyquist frequency is above them (100 teeth at 12 rpm: 20 Hz, so 50 Hz rows and faster).
  /// 0: diagnose takes the model's coupling's (formula_candidate alone offers none); negative: none.
  int teeth = 0;
  /// Offer only terms that vary faster than a slow drift: no t, t^2, t^3, steps, temperature,
  /// cycles of 10 s and longer, or any term whose column carries a level over the rows (more than
  /// 5 % of its squares in its mean on each channel: a constant, torque on one channel; a zero
  /// drift's level over one run is the slowest drift of all). For the search on the dense rows of a long recording: more rows add
  /// independent samples of a fast term, not of a slow one, whose effective count is set by the
  /// noise's drift; there a slow term fitted the bridge's wander (a temperature term and a step
  /// beside a 0.4 Hz pickup; a 705 N·m constant, the training run's drift level, that cost the
  /// next run 2 points). For the same reason each channel's level over the rows is taken out of
  /// the residual and of every column, so that no term takes it (a torque term did, the torque
  /// being positive): the candidate's held-out residual is about each channel's mean.
  bool fast_terms_only = false;
};

/// The time_cycle, step and ringing terms of `residual` on `rows` (in time order): the dominant cycle
/// (cycle_period.h), change in mean (change_point.h) and mode of the rig (ringing_estimate.h), each
/// where it stands out of the noise. The three run side by side on `parallel`, which also shares
/// the ringing's grid.
std::vector<std::string> time_terms_for(std::span<const RecordedSample> observations, std::span<const std::size_t> rows,
                                        const Eigen::MatrixX2d& residual, const ParallelFor& parallel = serial_for());

/// The terms every listed row can evaluate, as columns: rows k (M_sy') and n + k (M_sz') for
/// observations[rows[k]], with the model's moments taken as measured minus `residual`. The
/// catalogue's terms, then `extra` (time_cycle terms, made for a period).
struct TermDesign {
  std::vector<std::string> terms;
  Eigen::MatrixXd columns;  ///< 2n x terms [N·m per coefficient unit]
};
TermDesign term_design(std::span<const RecordedSample> observations, std::span<const std::size_t> rows,
                       const Eigen::MatrixX2d& residual, const std::vector<std::string>& extra = {});

/// The formula candidate for `residual` on `rows` (the search rows, in time order, as `folds` cut
/// them); nullopt when the sparse regression keeps no term.
std::optional<CandidateScore> formula_candidate(std::span<const RecordedSample> observations,
                                                std::span<const std::size_t> rows, const Eigen::MatrixX2d& residual,
                                                const Folds& folds, const FormulaSettings& settings);

/// `residual` less each channel's mean over its rows: what the fast-terms candidate
/// (FormulaSettings::fast_terms_only) is scored against.
Eigen::MatrixX2d without_levels(const Eigen::MatrixX2d& residual);

/// The held-out residual of the formula over `terms` on `residual` (each fold fitted on its
/// training rows, as formula_candidate scores); nullopt when a term cannot be evaluated there.
std::optional<Eigen::MatrixX2d> formula_held_out(std::span<const RecordedSample> observations,
                                                 std::span<const std::size_t> rows, const Eigen::MatrixX2d& residual,
                                                 const std::vector<std::string>& terms, const Folds& folds);

/// The formula over `terms` fitted by least squares on `rows` (e.g. the refit rows), with standard
/// errors; nullopt when a coefficient leaves its bound, or `terms` is empty.
std::optional<EffectFit> fit_formula(std::span<const RecordedSample> observations, std::span<const std::size_t> rows,
                                     const Eigen::MatrixX2d& residual, const std::vector<std::string>& terms,
                                     double variance_inflation);

}  // namespace gc
