// The campaign's hidden effects: each case turns the true programme (programme.h) into what the
// test cell's DAQ would log and measure, noise-free; daq_noise.h then adds the noise. Every
// effect is written here from its physical mechanism, with no code of the diagnosis or its effect
// library; the base physics is paper_model().predict at the TRUE inputs.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "core/measurement_sample.h"
#include "tests/diagnosis/campaign/daq_noise.h"
#include "tests/diagnosis/campaign/programme.h"

namespace gc::campaign {

/// What the DAQ logged (inputs) and the moments it would have measured without noise.
struct Recording {
  std::vector<InputRow> logged;        ///< logged inputs (the phase column is never written)
  std::vector<SensorMoments> truth;    ///< noise-free measured moments [N·m]
};

enum class Run { training, held_out };

/// One group of acceptable names: a claim matches when any regex of the group matches one of
/// its names (effect name, formula term name, or the verdict text for lag words).
struct NameGroup {
  std::string what;                    ///< in words, for the table
  std::vector<std::string> patterns;   ///< ECMAScript regexes, searched (not anchored)
  bool verdict_may_say = false;        ///< the verdict's text may match instead of a name
};

struct Case {
  std::string name;
  std::string truth_text;              ///< the hidden effect in words
  std::vector<NameGroup> must_name;    ///< every group must be matched (empty: claim nothing)
  /// Claims the truth rules out (regexes on the claimed names), checked on open cases too: a
  /// library effect that took a slice of the truth and stayed in the model as a wrong answer.
  std::vector<std::string> must_not_claim;
  NoiseSpec noise;
  std::size_t training_rows = 14150;
  std::size_t held_out_rows = 14150;
  double zeta_max_deg = 0.45;
  bool coarse_export = false;          ///< few digits (quantised case)
  std::uint64_t seed = 1;
  /// Fills `out` from the true inputs of one run.
  std::function<void(const std::vector<InputRow>& truth_inputs, Run run, Recording& out)> effect;
};

std::vector<Case> campaign_cases();

/// The base physics: the paper's model of the upwind coupling at these inputs (the TRUE ones
/// when called from a truth) [N·m]; parallel over rows.
std::vector<SensorMoments> base_moments(const std::vector<InputRow>& inputs);
SensorMoments base_moment(const InputRow& inputs);

/// The upwind coupling's jam angle as the CLI reports it [rad].
double jam_angle_rad();

}  // namespace gc::campaign
