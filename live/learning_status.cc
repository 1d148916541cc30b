#include "live/learning_status.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

namespace gc::live {

double window_to_judge_s(double rate_hz) {
  if (!(rate_hz > 0.0)) return 0.0;
  const double needed_s = 2.0 * static_cast<double>(kSamplesToJudge) / rate_hz;
  const double decade = std::pow(10.0, std::floor(std::log10(needed_s)));
  for (double step : {1.0, 2.0, 5.0, 10.0}) {
    if (step * decade >= needed_s * (1.0 - 1e-12)) return step * decade;
  }
  return 10.0 * decade;
}

namespace {

std::string rate_text(double rate_hz) { return fmt::format("{:.3g} Hz", rate_hz); }

/// Before the error is judged: at the noise level, or not enough samples to tell.
LearningStatus unjudged(const LearningInputs& in) {
  if (in.window_samples >= kSamplesToJudge) {
    return {"at_noise_level", "at the noise level: nothing to learn", 0};
  }
  const double holds = 0.5 * in.window_s * in.sample_rate_hz;   // the reported window at least
  if (in.sample_rate_hz > 0.0 && holds < static_cast<double>(kSamplesToJudge)) {
    return {"too_few_samples_in_window",
            fmt::format("too few samples in the window at {} ({} of the {} needed to tell the "
                        "error from the noise): give --window-s {:g}",
                        rate_text(in.sample_rate_hz), in.window_samples, kSamplesToJudge,
                        window_to_judge_s(in.sample_rate_hz)),
            0};
  }
  return {"gathering",
          fmt::format("gathering samples: {} of the {} needed to tell the error from the noise",
                      in.window_samples, kSamplesToJudge),
          0};
}

/// Beyond the noise, no diagnosis yet: what it waits for, the longer wait named.
LearningStatus waiting(const LearningInputs& in) {
  const std::uint64_t missing =
      in.rolling_samples < in.samples_needed ? in.samples_needed - in.rolling_samples : 0;
  const double timer_left_s = std::max(0.0, in.diagnose_after_s - in.beyond_noise_for_s);
  const double samples_left_s =
      in.sample_rate_hz > 0.0 ? static_cast<double>(missing) / in.sample_rate_hz : 0.0;
  if (missing > 0 && samples_left_s >= timer_left_s) {
    return {"waiting_for_samples",
            in.sample_rate_hz > 0.0
                ? fmt::format("beyond the noise; waiting for {} more samples for a diagnosis "
                              "(about {:.0f} s at {})",
                              missing, std::ceil(samples_left_s), rate_text(in.sample_rate_hz))
                : fmt::format("beyond the noise; waiting for {} more samples for a diagnosis", missing),
            missing};
  }
  if (in.found_nothing && in.next_diagnosis_in_s > 0.0) {
    return {"found_nothing",
            fmt::format("last diagnosis found nothing ({}); next in {:.0f} s",
                        *in.found_nothing, std::ceil(in.next_diagnosis_in_s)),
            missing};
  }
  return {"beyond_noise",
          fmt::format("beyond the noise for {:.0f} s; diagnosis in {:.0f} s",
                      std::floor(in.beyond_noise_for_s), std::ceil(timer_left_s)),
          missing};
}

}  // namespace

LearningStatus learning_status(const LearningInputs& in) {
  if (!in.enabled) return {"off", "learning off (--no-diagnosis)", 0};
  // A standing proposal first: a recheck of it running is upkeep, not news.
  if (in.standing_proposal) {
    return {"proposed",
            fmt::format("proposal {} standing: apply it (swap-model --proposal {} --operator NAME) "
                        "or leave it",
                        *in.standing_proposal, *in.standing_proposal),
            0};
  }
  if (in.diagnosis_running) return {"diagnosis_running", "diagnosis running", 0};
  if (in.diagnosis_queued) return {"diagnosis_queued", "diagnosis queued (one runs at a time)", 0};
  if (in.stale) return {"no_samples", "no samples: waiting for the test cell", 0};
  if (in.queue_full) {
    return {"queue_full", "diagnosis queue full (other cells first): tried again next period", 0};
  }
  return in.beyond_noise ? waiting(in) : unjudged(in);
}

}  // namespace gc::live
