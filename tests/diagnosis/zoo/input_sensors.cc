// Noise of the input sensors. The recording carries what they logged; the moments stay the
// model's prediction at the true inputs. Torque transducer (white or coloured, 0.02-0.5 % of the
// torque span); the two proximity probes that measure the misalignment vector (noise on each
// component, 0.05-0.4 % of the jam angle; the logged amplitude and direction are the vector's,
// so the direction is noisier at small amplitude, as a real rig's); the tachometer; the oil RTD.
#include <algorithm>
#include <cmath>
#include <numbers>

#include "tests/diagnosis/zoo/families.h"
#include "tests/diagnosis/zoo/text.h"

namespace gc::zoo {
namespace {
// White (phi = 0) or AR(1) unit noise, phi drawn from the correlation time 0.05-5 s.
Series sensor_noise(std::size_t n, double fs_hz, Rng& rng, double& tau_s) {
  tau_s = rng.chance(0.5) ? 0.0 : rng.log_uniform(0.05, 5.0);
  const double phi = tau_s > 0 ? std::exp(-1.0 / (tau_s * fs_hz)) : 0.0;
  return phi > 1e-3 ? ar1(n, phi, rng) : white(n, rng);
}
}  // namespace

std::string torque_transducer(const NoiseContext& c, Rng& rng, Channels& out) {
  const double sd = rng.log_uniform(2e-4, 5e-3) * c.torque_span_nm;
  double tau = 0;
  Series e = sensor_noise(out.rows(), c.fs_hz, rng, tau);
  scale_to(e, sd);
  double lowest = 1e300;
  for (double t : c.truth->torque_nm) lowest = std::min(lowest, t);
  for (std::size_t i = 0; i < out.rows(); ++i) out.torque_nm[i] = std::max(0.5 * lowest, out.torque_nm[i] + e[i]);
  return format("torque transducer %.0f N·m (%.2f%% of span) tau %.2g s", sd, 100 * sd / c.torque_span_nm, tau);
}

std::string proximity_probes(const NoiseContext& c, Rng& rng, Channels& out) {
  const double sd = rng.log_uniform(5e-4, 4e-3) * c.jam_rad;
  double tau = 0;
  Series ex = sensor_noise(out.rows(), c.fs_hz, rng, tau), ey = tau > 0 ? ar1(out.rows(), std::exp(-1.0 / (tau * c.fs_hz)), rng) : white(out.rows(), rng);
  scale_to(ex, sd);
  scale_to(ey, sd);
  for (std::size_t i = 0; i < out.rows(); ++i) {
    const double z = c.truth->zeta_rad[i], b = c.truth->beta_rad[i];
    const double x = z * std::cos(b) + ex[i], y = z * std::sin(b) + ey[i];
    out.zeta_rad[i] = std::hypot(x, y);
    // The logged direction unwrapped next to the true one (no 2 pi jumps in the column).
    out.beta_rad[i] = b + std::remainder(std::atan2(y, x) - b, 2.0 * std::numbers::pi);
  }
  return format("proximity probes %.2e rad per axis (%.2f%% of jam) tau %.2g s", sd, 100 * sd / c.jam_rad, tau);
}

std::string tachometer(const NoiseContext& c, Rng& rng, Channels& out) {
  const double sd = rng.uniform(0.01, 0.2);
  for (double& v : out.speed_rpm) v = std::max(0.5, v + sd * rng.normal());
  return format("tachometer %.3f rpm", sd);
}

std::string oil_rtd(const NoiseContext& c, Rng& rng, Channels& out) {
  const double sd = rng.uniform(0.02, 0.3), phi = rng.chance(0.5) ? 0.0 : rng.uniform(0.5, 0.99);
  Series e = phi > 0 ? ar1(out.rows(), phi, rng) : white(out.rows(), rng);
  scale_to(e, sd);
  for (std::size_t i = 0; i < out.rows(); ++i) out.temperature_c[i] += e[i];
  return format("oil RTD %.2f degC phi %.2f", sd, phi);
}

}  // namespace gc::zoo
