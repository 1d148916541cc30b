#include "diagnosis/synthesis/synthesize.h"

#include <cmath>
#include <numbers>
#include <vector>

#include "core/input_rate.h"
#include "core/loading_direction.h"
#include "core/model_error.h"
#include "core/rotation_phase.h"

namespace gc {
namespace {

std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

// Uniform in (0, 1]: 53 random bits, never zero so that log() is finite.
double open_uniform(std::uint64_t bits) {
  return (static_cast<double>(bits >> 11) + 1.0) * 0x1.0p-53;
}

}  // namespace

double standard_normal(std::uint64_t seed, std::uint64_t index, std::uint64_t stream) {
  const std::uint64_t key = splitmix64(seed ^ splitmix64(index * 2 + stream * 0x5851f42d4c957f2dULL));
  const double u1 = open_uniform(splitmix64(key));
  const double u2 = open_uniform(splitmix64(key ^ 0xd1b54a32d192ed03ULL));
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

SynthesizedRecording synthesize(const CouplingModel& model,
                                std::span<const MeasurementSample> inputs,
                                const SynthesisOptions& options) {
  require_non_negative("synthesis.noise_nm", options.noise_nm);
  SynthesizedRecording recording;
  recording.samples.reserve(inputs.size());
  // Derived inputs from the whole sequence first, as the recording reader does.
  std::vector<MeasurementSample> derived(inputs.begin(), inputs.end());
  derive_loading_directions(derived);
  derive_rotation_phase(derived);  // where every input has a speed
  derive_input_rates(derived);
  for (std::size_t i = 0; i < derived.size(); ++i) {
    RecordedSample sample{derived[i], {}, std::nullopt};
    try {
      const SensorMoments moments = model.predict_at(std::span<const MeasurementSample>(derived), i).moments;
      sample.measured.y_nm = moments.y_nm + options.noise_nm * standard_normal(options.seed, i, 0);
      sample.measured.z_nm = moments.z_nm + options.noise_nm * standard_normal(options.seed, i, 1);
      recording.samples.push_back(sample);
    } catch (const ModelError& error) {
      recording.rejected.push_back({i, error.what()});
    }
  }
  return recording;
}

}  // namespace gc
