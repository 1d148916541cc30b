// Test-cell noise on the two bending channels, reproducible by seed: white strain-gauge noise,
// coloured (AR(1)) noise from structural resonances and filtering, spikes from the telemetry,
// and a slow zero drift of the bridge offsets. Own generator (SplitMix64 + Box-Muller), so that
// the numbers are the same on every platform and independent of the library's synthesis code.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/measurement_sample.h"

namespace gc::independent {

/// SplitMix64 (Steele, Lea, Flood 2014) with Box-Muller normals: a small, portable stream.
class NoiseStream {
 public:
  explicit NoiseStream(std::uint64_t seed) : state_(seed) {}
  std::uint64_t next_bits();
  double uniform();          ///< in (0, 1]
  double standard_normal();  ///< N(0, 1), one Box-Muller value per call (the cosine branch)

 private:
  std::uint64_t state_;
};

/// Per-sample noise on (M_sy', M_sz') [N·m]; `count` samples, channels from independent streams.
using ChannelNoise = std::vector<SensorMoments>;

/// Independent N(0, sigma^2) on each channel [N·m].
ChannelNoise white_noise(std::size_t count, double sigma_nm, std::uint64_t seed);

/// x_i = phi x_(i-1) + e_i with e ~ N(0, sigma^2 (1 - phi^2)): the marginal standard deviation is
/// sigma [N·m] from the first sample on (x_0 drawn from the stationary law). |phi| < 1.
ChannelNoise ar1_noise(std::size_t count, double phi, double sigma_nm, std::uint64_t seed);

/// White noise of sigma plus, on a share of the samples (per channel), an outlier of
/// outlier_sigmas * sigma with a random sign: telemetry dropouts and bit errors [N·m].
ChannelNoise spiky_noise(std::size_t count, double sigma_nm, double outlier_share,
                         double outlier_sigmas, std::uint64_t seed);

/// A random walk of the channel offsets with N(0, step^2) steps per sample, starting at zero:
/// a bridge zero that wanders with temperature [N·m]. `y`, `z` choose the channels it acts on.
ChannelNoise random_walk_drift(std::size_t count, double step_nm, std::uint64_t seed, bool y = true,
                               bool z = true);

/// A low-frequency sine on the channel offsets, amplitude [N·m], period [s], with a phase drawn
/// from the seed: a zero that breathes with the cell's temperature cycle.
ChannelNoise sine_drift(const std::vector<double>& times_s, double amplitude_nm, double period_s,
                        std::uint64_t seed, bool y = true, bool z = true);

/// Sample-wise sum of noises of equal length.
ChannelNoise operator+(const ChannelNoise& a, const ChannelNoise& b);

}  // namespace gc::independent
