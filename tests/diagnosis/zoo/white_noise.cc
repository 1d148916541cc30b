// White noise of the strain-gauge bridges and their amplifiers: Gaussian, or heavy-tailed
// (Student-t, Laplace) as amplifier pops and telemetry glitches make it. Independent per channel.
#include <cmath>

#include "tests/diagnosis/zoo/families.h"
#include "tests/diagnosis/zoo/text.h"

namespace gc::zoo {

void add_moments(Channels& logged, Series y, Series z, double rms) {
  scale_to(y, rms);
  scale_to(z, rms);
  for (std::size_t i = 0; i < logged.rows(); ++i) {
    logged.msy_nm[i] += y[i];
    logged.msz_nm[i] += z[i];
  }
}

std::string white_gaussian(const NoiseContext& c, Rng& rng, Channels& out) {
  const std::size_t n = out.rows();
  add_moments(out, white(n, rng), white(n, rng), c.level_nm);
  return format("white %.0f N·m", c.level_nm);
}

std::string student_t(const NoiseContext& c, Rng& rng, Channels& out) {
  const double dof = rng.uniform(2.5, 10.0);  // variance finite for dof > 2
  const std::size_t n = out.rows();
  Series y(n), z(n);
  for (std::size_t i = 0; i < n; ++i) y[i] = rng.student_t(dof), z[i] = rng.student_t(dof);
  add_moments(out, y, z, c.level_nm);
  return format("student_t dof %.1f rms %.0f N·m", dof, c.level_nm);
}

std::string laplace(const NoiseContext& c, Rng& rng, Channels& out) {
  const std::size_t n = out.rows();
  Series y(n), z(n);
  for (std::size_t i = 0; i < n; ++i) y[i] = rng.laplace(), z[i] = rng.laplace();
  add_moments(out, y, z, c.level_nm);
  return format("laplace rms %.0f N·m", c.level_nm);
}

}  // namespace gc::zoo
