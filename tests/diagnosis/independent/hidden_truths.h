// The cases of issue 8's generalisation proof: a base model, a recording whose truth carries
// physics the base lacks (written in tests/diagnosis/independent/truth_physics.h's own forms, not
// core/effects/), realistic test-cell noise, a held-out recording of the same inputs with other
// noise, and what a diagnosis should name.
#pragma once

#include <string>
#include <vector>

#include "core/coupling_model.h"
#include "core/measurement_sample.h"
#include "core/recorded_sample.h"

namespace gc::independent {

/// What a verdict must name to count as naming the physics.
struct ExpectedNaming {
  /// Library effects any of which, added by the diagnosis, names it (e.g. {"friction"}).
  std::vector<std::string> effects;
  /// Lowercase words any of which, in the summary, names it (a formula's mechanism, e.g. "speed").
  std::vector<std::string> keywords;
  /// Noise only: nothing may be added and every round must say noise.
  bool noise = false;
  /// How many distinct expected names must be met (2 for two hidden effects at once).
  std::size_t min_named = 1;
};

struct HiddenTruthCase {
  std::string name;
  std::string physics;                      ///< what was hidden, one line
  std::string noise;                        ///< what noise was added, one line
  CouplingModel base;
  std::vector<MeasurementSample> inputs;    ///< shared by both recordings
  std::vector<SensorMoments> truth;         ///< noise-free measured moments [N·m]
  std::vector<RecordedSample> training;     ///< truth + noise (seed A): what diagnose sees
  std::vector<RecordedSample> held_out;     ///< truth + noise (seed B): what it is judged on
  ExpectedNaming expected;
};

/// Every case name, in a fixed order.
std::vector<std::string> hidden_truth_names();

/// Builds one case (a few hundred milliseconds: two base-model passes). Throws
/// std::invalid_argument for an unknown name.
HiddenTruthCase hidden_truth_case(const std::string& name);

/// About 1-2 % of the induced moments at 1-1.5 MN·m and 0.4 deg: strain-gauge noise of the paper's
/// test cell order, as tests/diagnosis/hidden_effects_test.cc [N·m].
constexpr double kNoiseSigmaNm = 2000.0;

}  // namespace gc::independent
