// Noise whose level or form changes: a level modulated by a slow random process, a level growing
// with the torque (a bridge excited harder, gauge noise proportional to strain), GARCH volatility
// clusters, noise correlated between the two channels (one amplifier, one supply), random
// telegraph (popcorn) bursts, and isolated telemetry spikes.
#include <algorithm>
#include <cmath>

#include "tests/diagnosis/zoo/families.h"
#include "tests/diagnosis/zoo/text.h"

namespace gc::zoo {

std::string slow_heteroscedastic(const NoiseContext& c, Rng& rng, Channels& out) {
  const std::size_t n = out.rows();
  const double log_sd = rng.uniform(0.2, 0.8), tau_rows = rng.uniform(0.01, 0.2) * static_cast<double>(n);
  const Series level = ar1(n, std::exp(-1.0 / tau_rows), rng);
  Series y = white(n, rng), z = white(n, rng);
  for (std::size_t i = 0; i < n; ++i) {
    const double g = std::exp(log_sd * level[i]);
    y[i] *= g, z[i] *= g;
  }
  add_moments(out, y, z, c.level_nm);
  return format("level x exp(OU sd %.2f, tau %.3g s) rms %.0f N·m", log_sd, tau_rows / c.fs_hz, c.level_nm);
}

std::string torque_heteroscedastic(const NoiseContext& c, Rng& rng, Channels& out) {
  const std::size_t n = out.rows();
  const double floor_share = rng.uniform(0.1, 0.6);  // the level at zero torque, relative to full
  double tmax = 0.0;
  for (double t : c.truth->torque_nm) tmax = std::max(tmax, t);
  Series y = white(n, rng), z = white(n, rng);
  for (std::size_t i = 0; i < n; ++i) {
    const double g = floor_share + (1.0 - floor_share) * c.truth->torque_nm[i] / tmax;
    y[i] *= g, z[i] *= g;
  }
  add_moments(out, y, z, c.level_nm);
  return format("level growing with torque (floor %.0f%%) rms %.0f N·m", 100 * floor_share, c.level_nm);
}

std::string garch_clusters(const NoiseContext& c, Rng& rng, Channels& out) {
  const std::size_t n = out.rows();
  const double alpha = rng.uniform(0.05, 0.15), beta = rng.uniform(0.75, 0.985 - alpha);
  auto garch = [&]() {
    Series x(n);
    double var = 1.0, e = 0.0;
    for (std::size_t i = 0; i < n + 200; ++i) {
      var = (1.0 - alpha - beta) + alpha * e * e + beta * var;
      e = std::sqrt(var) * rng.normal();
      if (i >= 200) x[i - 200] = e;
    }
    return x;
  };
  Series y = garch(), z = garch();
  add_moments(out, y, z, c.level_nm);
  return format("garch(1,1) alpha %.3f beta %.3f rms %.0f N·m", alpha, beta, c.level_nm);
}

std::string cross_correlated(const NoiseContext& c, Rng& rng, Channels& out) {
  const std::size_t n = out.rows();
  const double rho = rng.uniform(-0.9, 0.9);
  const double phi = rng.chance(0.5) ? 0.0 : rng.uniform(0.3, 0.95);
  const Series a = phi > 0 ? ar1(n, phi, rng) : white(n, rng), b = phi > 0 ? ar1(n, phi, rng) : white(n, rng);
  Series z(n);
  for (std::size_t i = 0; i < n; ++i) z[i] = rho * a[i] + std::sqrt(1 - rho * rho) * b[i];
  add_moments(out, a, z, c.level_nm);
  return format("y-z correlated rho %.2f phi %.2f rms %.0f N·m", rho, phi, c.level_nm);
}

std::string burst_telegraph(const NoiseContext& c, Rng& rng, Channels& out) {
  const std::size_t n = out.rows();
  // Popcorn noise: a level jumping between -a and +a at random (mean dwell 5..500 samples, at
  // most a fiftieth of the record) on top of white noise.
  const double dwell = std::min(rng.log_uniform(5.0, 500.0), static_cast<double>(n) / 50.0);
  const double share = rng.uniform(0.3, 0.8);
  auto telegraph = [&]() {
    Series x(n);
    double s = rng.chance(0.5) ? 1.0 : -1.0;
    for (double& v : x) {
      if (rng.chance(1.0 / dwell)) s = -s;
      v = s;
    }
    return x;
  };
  add_moments(out, telegraph(), telegraph(), c.level_nm * share);
  add_moments(out, white(n, rng), white(n, rng), c.level_nm * std::sqrt(1 - share * share));
  return format("random telegraph dwell %.0f samples (%.0f%% of level) + white, rms %.0f N·m", dwell, 100 * share, c.level_nm);
}

std::string isolated_spikes(const NoiseContext& c, Rng& rng, Channels& out) {
  const std::size_t n = out.rows();
  const double rate = rng.log_uniform(1e-4, 3e-3), size = rng.uniform(6.0, 30.0);
  add_moments(out, white(n, rng), white(n, rng), c.level_nm);
  std::size_t count = 0;
  for (std::size_t i = 0; i < n; ++i) {
    for (auto* ch : {&out.msy_nm, &out.msz_nm}) {
      if (rng.chance(rate)) {
        (*ch)[i] += (rng.chance(0.5) ? 1 : -1) * size * c.level_nm * rng.uniform(0.7, 1.3);
        ++count;
      }
    }
  }
  return format("white %.0f N·m + %zu isolated spikes (rate %.1e, %.0fx)", c.level_nm, count, rate, size);
}

}  // namespace gc::zoo
