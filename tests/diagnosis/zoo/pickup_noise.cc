// Mains pickup: 50 or 60 Hz from the drive's cabling, never a clean tone. The grid frequency
// wanders (an OU process of 0.01-0.1 Hz), the phase diffuses (a Lorentzian line 0.05-0.5 Hz wide)
// and the amplitude breathes; sampled at the DAQ's rate it aliases wherever the rate puts it (to
// near zero frequency at 10 Hz). Possibly with a third harmonic. Narrowband noise.
#include <cmath>
#include <numbers>

#include "tests/diagnosis/zoo/families.h"
#include "tests/diagnosis/zoo/text.h"

namespace gc::zoo {

std::string mains_pickup(const NoiseContext& c, Rng& rng, Channels& out) {
  const std::size_t n = out.rows();
  const double f0 = rng.chance(0.5) ? 50.0 : 60.0;
  const double wander_hz = rng.uniform(0.01, 0.1), wander_tau_s = rng.uniform(2.0, 60.0);
  const double linewidth_hz = rng.log_uniform(0.05, 0.5);
  const double third = rng.chance(0.5) ? rng.uniform(0.1, 0.5) : 0.0;
  const double dt = 1.0 / c.fs_hz, two_pi = 2.0 * std::numbers::pi;
  auto pickup = [&]() {
    Series x(n);
    double df = wander_hz * rng.normal(), theta = two_pi * rng.uniform(), theta3 = two_pi * rng.uniform(), log_a = 0.0;
    const double a_f = std::exp(-dt / wander_tau_s), a_a = std::exp(-dt / 10.0);
    const double diffusion = std::sqrt(two_pi * linewidth_hz * dt);
    for (std::size_t i = 0; i < n; ++i) {
      df = a_f * df + std::sqrt(1 - a_f * a_f) * wander_hz * rng.normal();
      log_a = a_a * log_a + std::sqrt(1 - a_a * a_a) * 0.3 * rng.normal();
      const double step = two_pi * (f0 + df) * dt;
      theta = std::fmod(theta + step + diffusion * rng.normal(), two_pi);
      theta3 = std::fmod(theta3 + 3.0 * step + diffusion * rng.normal(), two_pi);
      x[i] = std::exp(log_a) * (std::cos(theta) + third * std::cos(theta3));
    }
    return x;
  };
  Series y = pickup();
  Series z = rng.chance(0.5) ? pickup() : y;  // the same pickup on both channels, or each its own
  if (&z != &y && rng.chance(0.5)) for (double& v : z) v = -v;
  add_moments(out, y, z, c.level_nm);
  return format("mains %.0f Hz wander %.3f Hz/%.0f s line %.2f Hz 3rd %.2f rms %.0f N·m", f0, wander_hz, wander_tau_s,
                linewidth_hz, third, c.level_nm);
}

}  // namespace gc::zoo
