// The inputs are measured too. A model fed a noisy torque or misalignment channel predicts the
// sensors' noise as moments that the bridges never saw, and any average of the inputs removes it
// from the prediction: moment_delay, fitted to such a residual, finds a window (an average over a
// fraction of a revolution, a delay of a few samples) and a real held-out gain with no lag in the
// data. A lag is told from noise by its direction in time: a centred average of the inputs smooths
// their noise as well, and cannot shift the prediction. An effect that times the inputs is claimed
// only when it beats the centred average it could be, as it must beat the model.
#pragma once

#include <functional>
#include <optional>
#include <span>
#include <vector>

#include <Eigen/Dense>

#include "core/coupling_model.h"
#include "diagnosis/candidate_score.h"
#include "diagnosis/cross_validation_folds.h"
#include "diagnosis/formula_search.h"
#include "diagnosis/input_shrinkage.h"
#include "diagnosis/parallel_for.h"
#include "core/effects/effect_registry.h"
#include "core/recorded_sample.h"

namespace gc {

/// The nuisance a timing effect is judged against: the inputs averaged over `window_s` [s], 0 to
/// 5 s, centred on each sample's time (InputTiming{-window_s / 2, window_s}). Not a library effect:
/// the diagnosis names it, never claims it.
const EffectRegistration& centred_input_average();

/// Marks failed (CandidateScore::failure) each of `ranking`'s candidates that times the inputs
/// (Effect::times_inputs) and for which `claimable` holds, when its held-out residual does not beat
/// the centred input average's on the same folds by a block-paired t of `least_t` (the blocks
/// independent, as between candidates). The centred average is fitted once, and only when needed.
/// Returns the average's score when it was fitted.
std::optional<CandidateScore> demote_what_input_noise_explains(
    std::vector<CandidateScore>& ranking, const CouplingModel& model, std::span<const RecordedSample> observations,
    std::span<const std::size_t> rows, const Eigen::MatrixX2d& base, const Folds& folds, const ParallelFor& parallel,
    const CrossValidationSettings& settings, double least_t,
    const std::function<bool(const CandidateScore&)>& claimable);

/// The shrinks of the inputs (input_shrinkage.h) that let `model` best predict the moments of
/// `search` (positions of `rows`, which are in time order): channel by channel, a window of 0.25 to
/// 64 s (at least two samples, at most a quarter of the recording) keeping 0 or half of the
/// departure, the one with the least mean square kept. In sample: a nuisance is never claimed, and
/// the choice that flatters it only makes a claim beside it harder. None when nothing lowers it.
InputShrinks fit_input_shrinks(const CouplingModel& model, std::span<const RecordedSample> observations,
                               std::span<const std::size_t> rows, std::span<const std::size_t> search,
                               const ParallelFor& parallel);

/// The recording with its inputs read back by fit_input_shrinks, and `model`'s residual on
/// `search` of it: the model a claim must beat when the inputs are noisy. nullopt when no shrink
/// lowers the mean square, or the model cannot predict a row of it.
struct ReadBackInputs {
  InputShrinks shrinks;
  std::vector<RecordedSample> recording;
  Eigen::MatrixX2d residual;  ///< measured minus predicted, one row per search row [N·m]
};
std::optional<ReadBackInputs> read_back_inputs(const CouplingModel& model, std::span<const RecordedSample> observations,
                                               std::span<const std::size_t> rows, std::span<const std::size_t> search,
                                               const ParallelFor& parallel);

/// read_back_inputs, made at the first ask and kept: a round's effects, formula and signature are
/// judged against one read-back model, which costs a search of windows to make.
class ReadBackOnce {
 public:
  ReadBackOnce(const CouplingModel& model, std::span<const RecordedSample> observations,
               std::span<const std::size_t> rows, std::span<const std::size_t> search, const ParallelFor& parallel)
      : model_(model), observations_(observations), rows_(rows), search_(search), parallel_(parallel) {}
  const std::optional<ReadBackInputs>& get();
  /// The same read-back model (get()'s shrinks, fitted on the search rows) at `other` rows (a subset
  /// of rows, ascending): a formula found on a long recording's dense rows is judged there. nullopt
  /// when get() is, or the model cannot predict one of them.
  std::optional<ReadBackInputs> at(std::span<const std::size_t> other);

 private:
  const CouplingModel& model_;
  std::span<const RecordedSample> observations_;
  std::span<const std::size_t> rows_, search_;
  const ParallelFor& parallel_;
  bool made_ = false;
  std::optional<ReadBackInputs> read_back_;
};

/// Errors in the inputs, for every effect (timing ones after the centred average above): marks
/// failed (CandidateScore::failure) each of `ranking`'s effects for which
/// `claimable` holds and that does not beat `model` fed the inputs
/// read back by fit_input_shrinks by the paired t of `least_t` it met against `model` itself
/// (CandidateScore::against_base, on the same blocks), either
/// as scored (on the inputs as recorded) or refitted fold by fold on the inputs read back: the gain
/// it had came from the input sensors' noise, which the model carries into its prediction. Returns the shrinks when any were fitted and used.
std::optional<InputShrinks> demote_what_noisy_inputs_explain(
    std::vector<CandidateScore>& ranking, const CouplingModel& model, ReadBackOnce& read_back,
    std::span<const std::size_t> search, const Folds& folds,
    const ParallelFor& parallel, const CrossValidationSettings& settings, double least_t,
    const std::function<bool(const CandidateScore&)>& claimable,
    const std::function<std::optional<EffectRegistration>(const Effect&)>& registration_for);

/// The same for a formula (formula_search.h): marks `formula` failed when `claimable` holds and it
/// beats the model fed its inputs read back (`cleaner`, on the formula's rows) by a block-paired t
/// under `least_t`, neither as fitted nor as the formula searched afresh on the read-back model's
/// residual. A formula's terms reach what no effect does: the model's own moments. On noisy
/// proximity probes at a small misalignment the model's M_sz' carried the direction's noise, and a
/// gain of -0.9 on it took 56 % of the held-out error (a noise zoo draw, seed 20261211, draw 74);
/// the read-back model has none of it. A ringing of the torque (h * T - T, a low-pass less the
/// input) is a smoother of a noisy torque channel: on a 399 Hz recording with a transducer's white
/// noise, a 1.06 Hz mode took 15 % of the dense rows' held-out error (seed 20261281, draw 445).
void demote_formula_that_noisy_inputs_explain(CandidateScore& formula, const ReadBackInputs& cleaner,
                                              std::span<const RecordedSample> observations,
                                              std::span<const std::size_t> rows, const Folds& folds,
                                              const FormulaSettings& settings, double least_t,
                                              const std::function<bool(const CandidateScore&)>& claimable);

}  // namespace gc
