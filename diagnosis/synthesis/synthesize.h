// Synthetic recordings: a model's predictions along a load sequence plus Gaussian noise on the
// measured moments. Reproducible: the noise of sample i depends only on the seed and i, so the
// same seed gives the same numbers in any order and on any number of threads.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "core/coupling_model.h"
#include "core/recorded_sample.h"

namespace gc {

/// A standard normal number for (seed, index, stream): a counter-based generator (SplitMix64
/// and Box-Muller), identical on every platform, unlike std::normal_distribution.
double standard_normal(std::uint64_t seed, std::uint64_t index, std::uint64_t stream);

struct SynthesisOptions {
  double noise_nm = 0.0;     ///< standard deviation of the noise on each moment channel [N·m]
  std::uint64_t seed = 1;
};

struct SynthesisRejection {
  std::size_t index;         ///< position in the input sequence
  std::string reason;        ///< the model's error message
};

struct SynthesizedRecording {
  std::vector<RecordedSample> samples;        ///< the predictions the model accepted
  std::vector<SynthesisRejection> rejected;   ///< the inputs it refused (e.g. beyond the jam)
};

/// Predicts every input with `model`, adds noise; inputs the model rejects are listed, not
/// dropped in silence. Before the model sees them, as the recording reader does, the derived
/// inputs are set from the whole sequence: loading directions, with the dead band from its
/// misalignment noise (core/loading_direction.h), and the rotation phase where every input has a
/// speed (core/rotation_phase.h). Throws InvalidInput for a negative or non-finite noise.
SynthesizedRecording synthesize(const CouplingModel& model,
                                std::span<const MeasurementSample> inputs,
                                const SynthesisOptions& options);

}  // namespace gc
