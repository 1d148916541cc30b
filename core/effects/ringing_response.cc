#include "core/effects/ringing_response.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <complex>
#include <numbers>

namespace gc {

RingingPole::RingingPole(const RingingMode& m) {
  const double wn = 2.0 * std::numbers::pi * m.natural_frequency_hz;
  const double root = std::sqrt(1.0 - m.damping_ratio * m.damping_ratio);
  s_ = {-m.damping_ratio * wn, wn * root};
  a_ = {-1.0, m.damping_ratio / root};
  gaps_.fill(std::numeric_limits<double>::quiet_NaN());
}

namespace {

/// Where a change is forgotten: e^{-zeta w_n tau} below this.
constexpr double kForgotten = 1e-6;

}  // namespace

std::vector<double> ringing_sequence(std::span<const double> times_s, std::span<const double> inputs,
                                     const RingingMode& mode) {
  RingingPole pole(mode);
  std::vector<double> r(inputs.size(), 0.0);
  std::complex<double> sum = 0.0;
  for (std::size_t i = 1; i < inputs.size(); ++i) {
    r[i] = pole.next(sum, times_s[i] - times_s[i - 1], inputs[i] - inputs[i - 1]);
  }
  return r;
}

double ringing_memory_s(const RingingMode& mode) {
  // -Re s of RingingPole, written out: a pole fills its 64-gap cache.
  return -std::log(kForgotten) / (mode.damping_ratio * (2.0 * std::numbers::pi * mode.natural_frequency_hz));
}

double torque_ringing_at(const InputHistory& history, const RingingMode& mode) {
  RingingPole pole(mode);
  const std::size_t i = history.index();
  const double t = history.at(i).time_s;
  const double memory_s = ringing_memory_s(mode);
  std::complex<double> factor = 1.0, sum = 0.0;  // factor = e^{s (t_i - t_k)}
  for (std::size_t k = i; k >= 1; --k) {
    const MeasurementSample& now = history.at(k);
    const MeasurementSample& before = history.at(k - 1);
    sum += pole.a() * (now.torque_nm - before.torque_nm) * factor;
    if (t - before.time_s > memory_s) break;
    factor *= pole.decay(now.time_s - before.time_s);
  }
  return sum.real();
}

}  // namespace gc
