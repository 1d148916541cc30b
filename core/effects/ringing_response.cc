#include "core/effects/ringing_response.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <complex>
#include <numbers>

namespace gc {
namespace {

/// s and A of the header's g(tau) = Re(A e^{s tau}).
struct Pole {
  std::complex<double> s, a;
  explicit Pole(const RingingMode& m) {
    const double wn = 2.0 * std::numbers::pi * m.natural_frequency_hz;
    const double root = std::sqrt(1.0 - m.damping_ratio * m.damping_ratio);
    s = {-m.damping_ratio * wn, wn * root};
    a = {-1.0, m.damping_ratio / root};
  }
  /// e^{s dt}, remembered per gap: a clock's gaps take a handful of values a few ulp apart (16 on
  /// a 100 Hz CSV's stamps), which alternate, and an exp per sample was a sixth of a diagnosis.
  std::complex<double> decay(double dt) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &dt, sizeof bits);
    const std::size_t slot = static_cast<std::size_t>((bits * 0x9E3779B97F4A7C15ull) >> 58);  // of 64
    if (!(gaps_[slot] == dt)) {
      gaps_[slot] = dt;
      decays_[slot] = std::exp(s * dt);
    }
    return decays_[slot];
  }

 private:
  std::array<double, 64> gaps_ = filled(std::numeric_limits<double>::quiet_NaN());
  std::array<std::complex<double>, 64> decays_{};

  static std::array<double, 64> filled(double value) {
    std::array<double, 64> a;
    a.fill(value);
    return a;
  }
};

/// Where a change is forgotten: e^{-zeta w_n tau} below this.
constexpr double kForgotten = 1e-6;

}  // namespace

std::vector<double> ringing_sequence(std::span<const double> times_s, std::span<const double> inputs,
                                     const RingingMode& mode) {
  Pole pole(mode);
  std::vector<double> r(inputs.size(), 0.0);
  std::complex<double> sum = 0.0;
  for (std::size_t i = 1; i < inputs.size(); ++i) {
    sum = sum * pole.decay(times_s[i] - times_s[i - 1]) + pole.a * (inputs[i] - inputs[i - 1]);
    r[i] = sum.real();
  }
  return r;
}

double ringing_memory_s(const RingingMode& mode) {
  // -Re s of Pole, written out: a Pole fills its 64-gap cache.
  return -std::log(kForgotten) / (mode.damping_ratio * (2.0 * std::numbers::pi * mode.natural_frequency_hz));
}

double torque_ringing_at(const InputHistory& history, const RingingMode& mode) {
  Pole pole(mode);
  const std::size_t i = history.index();
  const double t = history.at(i).time_s;
  const double memory_s = ringing_memory_s(mode);
  std::complex<double> factor = 1.0, sum = 0.0;  // factor = e^{s (t_i - t_k)}
  for (std::size_t k = i; k >= 1; --k) {
    const MeasurementSample& now = history.at(k);
    const MeasurementSample& before = history.at(k - 1);
    sum += pole.a * (now.torque_nm - before.torque_nm) * factor;
    if (t - before.time_s > memory_s) break;
    factor *= pole.decay(now.time_s - before.time_s);
  }
  return sum.real();
}

}  // namespace gc
