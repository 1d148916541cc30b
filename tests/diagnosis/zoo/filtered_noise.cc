// Noise the acquisition chain filters: white noise through an anti-alias low-pass or a band-pass,
// through a moving-average (boxcar) filter, held by a slower sensor (sample-and-hold: a telemetry
// link updating every k samples), or averaged over a carrier demodulator's window (about one
// revolution of the shaft). Only the noise is filtered: the moments themselves are not lagged.
#include <algorithm>
#include <cmath>

#include "tests/diagnosis/zoo/families.h"
#include "tests/diagnosis/zoo/text.h"

namespace gc::zoo {
namespace {
// White noise over burn + n samples, filtered, the first `burn` dropped: stationary from row 0.
template <typename F>
Series filtered_white(std::size_t n, std::size_t burn, Rng& rng, F filter) {
  Series y = filter(white(n + burn, rng));
  return Series(y.begin() + static_cast<long>(burn), y.end());
}
}  // namespace

std::string band_limited(const NoiseContext& c, Rng& rng, Channels& out) {
  const std::size_t n = out.rows();
  const bool band = rng.chance(0.5);
  const double f = rng.log_uniform(0.01, 0.4), q = band ? rng.uniform(0.5, 3.0) : rng.uniform(0.5, 1.0);
  const auto burn = static_cast<std::size_t>(std::min(1.0e5, 20.0 * q / f));
  auto filt = [&](const Series& x) { return band ? bandpass2(x, f, q) : lowpass2(x, f, q); };
  add_moments(out, filtered_white(n, burn, rng, filt), filtered_white(n, burn, rng, filt), c.level_nm);
  return format("%s %.3g Hz Q %.2f rms %.0f N·m", band ? "band-pass" : "low-pass", f * c.fs_hz, q, c.level_nm);
}

std::string moving_average_noise(const NoiseContext& c, Rng& rng, Channels& out) {
  const std::size_t n = out.rows();
  const auto m = static_cast<std::size_t>(rng.integer(2, static_cast<int>(std::clamp<std::size_t>(n / 50, 2, 50))));
  auto filt = [&](const Series& x) { return moving_average(x, m); };
  add_moments(out, filtered_white(n, m, rng, filt), filtered_white(n, m, rng, filt), c.level_nm);
  return format("moving average of %zu samples rms %.0f N·m", m, c.level_nm);
}

std::string sample_and_hold(const NoiseContext& c, Rng& rng, Channels& out) {
  const std::size_t n = out.rows();
  const int k = rng.integer(2, static_cast<int>(std::clamp<std::size_t>(n / 100, 2, 50)));
  // Each channel holds its own slower samples, started at a random phase.
  auto held = [&]() {
    Series x(n);
    double v = rng.normal();
    const int phase = rng.integer(0, k - 1);
    for (std::size_t i = 0; i < n; ++i) {
      if ((static_cast<int>(i) + phase) % k == 0) v = rng.normal();
      x[i] = v;
    }
    return x;
  };
  Series y = held(), z = held();
  add_moments(out, y, z, c.level_nm);
  return format("sample-and-hold every %d samples rms %.0f N·m", k, c.level_nm);
}

std::string demodulator_average(const NoiseContext& c, Rng& rng, Channels& out) {
  const std::size_t n = out.rows();
  // Window: a share of one revolution at the true speed [s], in samples (at least 1).
  const double share = rng.uniform(0.25, 1.0);
  std::vector<double> window(n);
  double longest = 1.0;
  for (std::size_t i = 0; i < n; ++i) {
    window[i] = std::max(1.0, share * 60.0 / c.truth->speed_rpm[i] * c.fs_hz);
    window[i] = std::min(window[i], std::max(1.0, 0.02 * static_cast<double>(n)));  // at most 2 % of the record
    longest = std::max(longest, window[i]);
  }
  const auto burn = static_cast<std::size_t>(longest);
  std::vector<double> w(burn, window.front());
  w.insert(w.end(), window.begin(), window.end());
  auto filt = [&](const Series& x) { return varying_average(x, w); };
  add_moments(out, filtered_white(n, burn, rng, filt), filtered_white(n, burn, rng, filt), c.level_nm);
  return format("demodulator average over %.2f rev (<= %.0f samples) rms %.0f N·m", share, longest, c.level_nm);
}

}  // namespace gc::zoo
