#include "diagnosis/mains_pickup.h"

#include <cmath>

#include "diagnosis/verdict_text.h"

namespace gc {
namespace {

/// Where a wave of `f` [Hz] shows when sampled at `fs` [Hz]: folded into [0, fs / 2].
double aliased(double f, double fs) {
  if (!(fs > 0.0) || !std::isfinite(fs)) return f;
  const double folded = std::fmod(f, fs);
  return folded > 0.5 * fs ? fs - folded : folded;
}

}  // namespace

std::optional<double> mains_frequency(double frequency_hz, double sample_rate_hz, double resolution_hz) {
  for (double base : {50.0, 60.0}) {
    for (int harmonic = 1; harmonic <= 3; ++harmonic) {
      const double mains = harmonic * base;
      const double seen = aliased(mains, sample_rate_hz);
      // A mains frequency aliased onto almost nothing is a drift, which other tests judge.
      if (seen < 2.0 * resolution_hz) continue;
      if (std::abs(seen - frequency_hz) <= resolution_hz + 0.005 * seen) return mains;
    }
  }
  return std::nullopt;
}

std::string mains_pickup_text(double cycle_hz, double mains_hz) {
  const std::string at = std::abs(cycle_hz - mains_hz) < 0.01 * mains_hz
                             ? short_number(mains_hz) + " Hz"
                             : short_number(cycle_hz) + " Hz (" + short_number(mains_hz) + " Hz aliased by the sample rate)";
  return "a cycle at " + at + " is mains pickup in the bridges or their cables, an instrument artefact: not offered "
         "as physics (screen and ground the bridge cables, or filter it)";
}

}  // namespace gc
