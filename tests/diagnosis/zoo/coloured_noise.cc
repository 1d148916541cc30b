// Coloured noise: the structure's broadband response and the bridges' slow zero. AR(1) (a first-
// order lag of white noise), AR(2) (a lightly damped structural mode excited by broadband forcing:
// a noise peak, never a tone), 1/f and 1/f^2, a correlated part hidden under white noise, and an
// Ornstein-Uhlenbeck zero wandering on a time scale of the record.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "tests/diagnosis/zoo/families.h"
#include "tests/diagnosis/zoo/text.h"

namespace gc::zoo {

std::string ar1_coloured(const NoiseContext& c, Rng& rng, Channels& out) {
  const double phi = 1.0 - rng.log_uniform(0.005, 0.7);  // 0.3 .. 0.995
  const std::size_t n = out.rows();
  add_moments(out, ar1(n, phi, rng), ar1(n, phi, rng), c.level_nm);
  return format("ar1 phi %.3f (tau %.3g s) rms %.0f N·m", phi, -1.0 / (c.fs_hz * std::log(phi)), c.level_nm);
}

std::string ar2_resonant_noise(const NoiseContext& c, Rng& rng, Channels& out) {
  const std::size_t n = out.rows();
  const double f = rng.log_uniform(0.01, 0.4);  // peak [cycles per sample]
  // Bandwidth: at least a twentieth of the peak frequency (Q <= 20) and at least 20 / record
  // cycles per sample (coherent over at most a twentieth of the record), so it is a noise peak.
  const double bw = std::max({f / 20.0, 20.0 / static_cast<double>(n), rng.log_uniform(f / 20.0, f / 2.0)});
  const double r = std::max(0.3, 1.0 - std::numbers::pi * bw);
  add_moments(out, ar2_resonant(n, f, r, rng), ar2_resonant(n, f, r, rng), c.level_nm);
  return format("ar2 peak %.3g Hz bandwidth %.3g Hz (r %.4f) rms %.0f N·m", f * c.fs_hz, bw * c.fs_hz, r, c.level_nm);
}

std::string pink_noise(const NoiseContext& c, Rng& rng, Channels& out) {
  const std::size_t n = out.rows();
  add_moments(out, pink(n, rng), pink(n, rng), c.level_nm);
  return format("pink 1/f rms %.0f N·m", c.level_nm);
}

std::string brown_noise(const NoiseContext& c, Rng& rng, Channels& out) {
  const std::size_t n = out.rows();
  add_moments(out, brown(n, rng), brown(n, rng), c.level_nm);
  return format("brown 1/f^2 rms %.0f N·m", c.level_nm);
}

std::string hidden_correlated(const NoiseContext& c, Rng& rng, Channels& out) {
  const std::size_t n = out.rows();
  const double phi = rng.uniform(0.98, 0.995), ratio = rng.uniform(1.0, 3.0);
  const double white_rms = c.level_nm / std::sqrt(1.0 + ratio * ratio);
  add_moments(out, white(n, rng), white(n, rng), white_rms);
  add_moments(out, ar1(n, phi, rng), ar1(n, phi, rng), ratio * white_rms);
  return format("hidden ar1 phi %.3f at %.1fx white %.0f N·m", phi, ratio, white_rms);
}

std::string wandering_zero(const NoiseContext& c, Rng& rng, Channels& out) {
  const std::size_t n = out.rows();
  const double tau_rows = rng.uniform(0.05, 0.5) * static_cast<double>(n);
  const double phi = std::exp(-1.0 / tau_rows);
  const double white_share = rng.uniform(0.3, 0.8);  // a bridge always has some white noise too
  add_moments(out, ar1(n, phi, rng), ar1(n, phi, rng), c.level_nm * std::sqrt(1 - white_share * white_share));
  add_moments(out, white(n, rng), white(n, rng), c.level_nm * white_share);
  return format("wandering zero OU tau %.3g s + white %.0f%%, rms %.0f N·m", tau_rows / c.fs_hz, 100 * white_share, c.level_nm);
}

}  // namespace gc::zoo
