#include "diagnosis/input_noise_check.h"

#include <algorithm>
#include <iomanip>
#include <limits>
#include <sstream>

#include "core/effects/registration.h"
#include "diagnosis/model_residuals.h"
#include "diagnosis/noise_estimate.h"
#include "diagnosis/row_selection.h"

namespace gc {
namespace {

const EffectInfo kInfo{
    "centred_input_average",
    "The inputs averaged over a window centred on each sample: what smooths the noise of the torque, "
    "misalignment and direction sensors out of the prediction without shifting it in time.",
    "none (a nuisance of the measurement, judged against moment_delay; docs/diagnosis.md)",
    {{"window_s", "s", "the window's length, centred on the sample's time", 0.0, 5.0, 0.0, 0.0, {0.0, 2.0}, false, 0.0,
      "the noise of the input channels (their sensors, filters and sampling)"}}};

class CentredInputAverage final : public Effect {
 public:
  explicit CentredInputAverage(const ParameterValues& values) : Effect(kInfo, values), window_s_(value("window_s")) {}

  bool times_inputs() const override { return !neutral(); }
  // A sample seen alone (no adjust_inputs) has no neighbours to average, and a centred window no
  // lag to undo.
  InputTiming input_timing(const MeasurementSample&) const override { return {-0.5 * window_s_, window_s_}; }

 private:
  double window_s_;
};

bool times_inputs(const CandidateScore& c) { return c.fit && c.fit->effect && c.fit->effect->times_inputs(); }

/// The model's mean square on `search` of the recording with inputs shrunk by `shrinker`; infinite when a row
/// cannot be predicted.
double shrunk_mean_square(const CouplingModel& model, InputShrinker& shrinker, std::span<const std::size_t> search,
                          const InputShrinks& shrinks, const ParallelFor& parallel) {
  // A model that reads each row alone needs the search rows read back, not the whole recording.
  const std::span<const RecordedSample> shrunk =
      model.reads_other_samples() ? shrinker.shrunk(shrinks) : shrinker.shrunk(shrinks, search);
  const ModelResiduals r = model_residuals(model, shrunk, search, parallel);
  return r.failed_rows.empty() ? pooled_mean_square(r.residual) : std::numeric_limits<double>::infinity();
}

/// The candidate refitted on `shrunk` fold by fold from its full fit, its residual on each fold's
/// held-out rows; nullopt when a fold cannot be refitted or predicted.
std::optional<Eigen::MatrixX2d> held_out_on(const CouplingModel& model, const CandidateScore& c,
                                            const EffectRegistration& registration,
                                            std::span<const RecordedSample> shrunk, std::span<const std::size_t> search,
                                            const Folds& folds, const ParallelFor& parallel, int iterations) {
  CouplingModel base = model;
  for (const std::string& name : c.replaces) base = base.without_effect(name);
  Eigen::MatrixX2d out = Eigen::MatrixX2d::Zero(static_cast<Eigen::Index>(search.size()), 2);
  for (std::size_t f = 0; f < folds.held_out.size(); ++f) {
    const std::optional<EffectFit> fold = refit_effect(base, registration, *c.fit, shrunk,
                                                       rows_at(search, folds.training[f]), parallel, iterations, false);
    if (!fold) return std::nullopt;
    const ModelResiduals r =
        model_residuals(base.with_effect(fold->effect), shrunk, rows_at(search, folds.held_out[f]), parallel);
    if (!r.failed_rows.empty()) return std::nullopt;
    for (std::size_t k = 0; k < folds.held_out[f].size(); ++k) {
      out.row(static_cast<Eigen::Index>(folds.held_out[f][k])) = r.residual.row(static_cast<Eigen::Index>(k));
    }
  }
  return out;
}

std::string described(const InputShrinks& s) {
  std::ostringstream out;
  out << std::setprecision(2);
  const auto one = [&](const char* name, const InputShrink& x) {
    if (x.none()) return;
    if (out.tellp() > 0) out << ", ";
    out << name << " over " << x.window_s << " s" << (x.median ? " (median)" : "") << " keeping " << 100.0 * x.keep << " %";
  };
  one("torque", s.torque);
  one("misalignment", s.misalignment);
  one("direction", s.direction);
  return out.str();
}

/// Why a candidate that did not beat the read-back model is failed: `how` it was judged.
std::string read_back_failure(const InputShrinks& shrinks, const char* how, double t, double least_t) {
  std::ostringstream why;
  why << "it does not beat the model fed its inputs read back toward their centred means (" << described(shrinks)
      << "), " << how << " (paired t " << std::setprecision(2) << t << ", under " << least_t
      << "): the input sensors' noise, which the model carries into its prediction, not physics";
  return why.str();
}

}  // namespace

const EffectRegistration& centred_input_average() {
  static const EffectRegistration registration = register_effect<CentredInputAverage>(kInfo);
  return registration;
}

std::optional<CandidateScore> demote_what_input_noise_explains(
    std::vector<CandidateScore>& ranking, const CouplingModel& model, std::span<const RecordedSample> observations,
    std::span<const std::size_t> rows, const Eigen::MatrixX2d& base, const Folds& folds, const ParallelFor& parallel,
    const CrossValidationSettings& settings, double least_t,
    const std::function<bool(const CandidateScore&)>& claimable) {
  std::optional<CandidateScore> centred;
  for (CandidateScore& c : ranking) {
    if (!times_inputs(c) || !claimable(c)) continue;
    if (!centred) {
      centred = score_candidate(model, centred_input_average(), observations, rows, base, folds, parallel, settings);
    }
    if (!centred->failure.empty()) continue;
    // Blocks as independent, as between any two candidates (paired_block_test.h): the noise the
    // two leave in common cancels in their difference.
    const PairedBlockTest t = paired_block_test(centred->held_out_residual, c.held_out_residual, folds.block_of,
                                                folds.blocks);
    if (t.t >= least_t) continue;
    std::ostringstream why;
    why << "a window of the inputs centred on each sample (" << std::setprecision(3)
        << centred->fit->parameters.front().value << " s) does about as well (paired t of the lag against it "
        << std::setprecision(2) << t.t << ", under " << least_t << "): the input sensors' noise, which the model carries into "
        << "its prediction, not a lag";
    c.failure = why.str();
  }
  std::stable_partition(ranking.begin(), ranking.end(), [](const CandidateScore& c) { return c.failure.empty(); });
  return centred;
}

InputShrinks fit_input_shrinks(const CouplingModel& model, std::span<const RecordedSample> observations,
                               std::span<const std::size_t> rows, std::span<const std::size_t> search,
                               const ParallelFor& parallel) {
  InputShrinks best;
  if (rows.size() < 2) return best;
  const double duration = observations[rows.back()].input.time_s - observations[rows.front()].input.time_s;
  const double interval = duration / static_cast<double>(rows.size() - 1);
  // The centres are made at the search rows alone for a model that reads each row alone.
  const std::span<const std::size_t> at = model.reads_other_samples() ? std::span<const std::size_t>{} : search;
  InputShrinker shrinker(observations, rows, at);
  double best_ms = shrunk_mean_square(model, shrinker, search, best, parallel);
  for (InputShrink InputShrinks::*channel : {&InputShrinks::torque, &InputShrinks::misalignment, &InputShrinks::direction}) {
    for (double window_s : {0.25, 1.0, 4.0, 16.0, 64.0}) {
      if (window_s < 2.0 * interval || window_s > 0.25 * duration) continue;
      // Torque and misalignment also by the median, which keeps a programme's steps and ramps; a
      // direction's turns are averaged as unit vectors (input_shrinkage.h).
      for (const bool median : {false, true}) {
        if (median && channel == &InputShrinks::direction) continue;
        for (double keep : {0.0, 0.5}) {
          InputShrinks trial = best;
          trial.*channel = {window_s, keep, median};
          const double ms = shrunk_mean_square(model, shrinker, search, trial, parallel);
          if (ms < best_ms) {
            best_ms = ms;
            best = trial;
          }
        }
      }
    }
  }
  return best;
}

namespace {

/// `model`'s residual at `at` (a subset of rows, ascending) of the recording read back by `shrinks`.
std::optional<ReadBackInputs> read_back_with(const CouplingModel& model, std::span<const RecordedSample> observations,
                                             std::span<const std::size_t> rows, const InputShrinks& shrinks,
                                             std::span<const std::size_t> at, const ParallelFor& parallel) {
  ReadBackInputs out;
  out.shrinks = shrinks;
  out.recording = with_shrunk_inputs(observations, rows, shrinks,
                                     model.reads_other_samples() ? std::span<const std::size_t>{} : at);
  ModelResiduals r = model_residuals(model, out.recording, at, parallel);
  if (!r.failed_rows.empty()) return std::nullopt;
  out.residual = std::move(r.residual);
  return out;
}

}  // namespace

std::optional<ReadBackInputs> read_back_inputs(const CouplingModel& model, std::span<const RecordedSample> observations,
                                               std::span<const std::size_t> rows, std::span<const std::size_t> search,
                                               const ParallelFor& parallel) {
  const InputShrinks shrinks = fit_input_shrinks(model, observations, rows, search, parallel);
  if (shrinks.none()) return std::nullopt;
  return read_back_with(model, observations, rows, shrinks, search, parallel);
}

const std::optional<ReadBackInputs>& ReadBackOnce::get() {
  if (!made_) read_back_ = read_back_inputs(model_, observations_, rows_, search_, parallel_);
  made_ = true;
  return read_back_;
}

std::optional<ReadBackInputs> ReadBackOnce::at(std::span<const std::size_t> other) {
  if (!get()) return std::nullopt;
  return read_back_with(model_, observations_, rows_, read_back_->shrinks, other, parallel_);
}

std::optional<InputShrinks> demote_what_noisy_inputs_explain(
    std::vector<CandidateScore>& ranking, const CouplingModel& model, ReadBackOnce& read_back_once,
    std::span<const std::size_t> search, const Folds& folds,
    const ParallelFor& parallel, const CrossValidationSettings& settings, double least_t,
    const std::function<bool(const CandidateScore&)>& claimable,
    const std::function<std::optional<EffectRegistration>(const Effect&)>& registration_for) {
  // Timing effects too: the centred window above reaches 5 s, and a moment_delay averaging over
  // revolutions of a slow shaft (1.8 revolutions at 3.7 Hz sampling) reached beyond it on white
  // probe noise. A real lag keeps its shift over the read-back inputs (a DAQ skew of 0.3 s, a
  // demodulator's trailing revolution).
  const auto tested = [&](const CandidateScore& c) { return c.fit && c.fit->effect && claimable(c); };
  if (std::none_of(ranking.begin(), ranking.end(), tested)) return std::nullopt;
  const std::optional<ReadBackInputs>& read_back = read_back_once.get();
  if (!read_back) return std::nullopt;
  const InputShrinks& shrinks = read_back->shrinks;
  const std::vector<RecordedSample>& shrunk = read_back->recording;
  for (CandidateScore& c : ranking) {
    if (!tested(c)) continue;
    const std::optional<EffectRegistration> registration = registration_for(*c.fit->effect);
    if (!registration) continue;
    // The effect with the inputs it does best with: as recorded (its score) or read back. Physics
    // on clean inputs keeps its whole gain over the read-back model, which may mimic a share of it
    // (a smoothed sweep bends as an offset does); a fit to the inputs' noise has none on either.
    // The test the claim met against the model (CandidateScore::against_base), on the same blocks.
    PairedBlockTest t = paired_block_test(read_back->residual, c.held_out_residual, folds.block_of, folds.blocks);
    if (t.t >= least_t) continue;
    const std::optional<Eigen::MatrixX2d> held_out =
        held_out_on(model, c, *registration, shrunk, search, folds, parallel, settings.fold_iterations);
    if (held_out) {
      const PairedBlockTest refitted = paired_block_test(read_back->residual, *held_out, folds.block_of, folds.blocks);
      if (refitted.t > t.t) t = refitted;
    }
    if (t.t >= least_t) continue;
    c.failure = read_back_failure(shrinks, "on the inputs as recorded or refitted on those", t.t, least_t);
  }
  std::stable_partition(ranking.begin(), ranking.end(), [](const CandidateScore& c) { return c.failure.empty(); });
  return shrinks;
}

void demote_formula_that_noisy_inputs_explain(CandidateScore& formula, const ReadBackInputs& cleaner,
                                              std::span<const RecordedSample> observations,
                                              std::span<const std::size_t> rows, const Folds& folds,
                                              const FormulaSettings& settings, double least_t,
                                              const std::function<bool(const CandidateScore&)>& claimable) {
  if (!formula.failure.empty() || !claimable(formula)) return;
  double t = paired_block_test(cleaner.residual, formula.held_out_residual, folds.block_of, folds.blocks).t;
  if (t < least_t) {
    // Physics on clean inputs is still there once the model's inputs are read back, and a formula
    // searched on what that model leaves finds it again.
    if (const std::optional<CandidateScore> again = formula_candidate(observations, rows, cleaner.residual, folds, settings)) {
      t = std::max(t, paired_block_test(cleaner.residual, again->held_out_residual, folds.block_of, folds.blocks).t);
    }
  }
  if (t >= least_t) return;
  formula.failure =
      read_back_failure(cleaner.shrinks, "as fitted or searched again on what that model leaves", t, least_t);
}

}  // namespace gc
