#include "diagnosis/input_noise_check.h"

#include <algorithm>
#include <iomanip>
#include <sstream>

#include "core/effects/registration.h"

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

}  // namespace gc
