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
  std::complex<double> decay(double dt) { return decay(dt, slot_of(dt)); }
  /// The same, its slot found already (slot_of): modes run side by side share it.
  std::complex<double> decay(double dt, std::size_t slot) {
    if (!(gaps_[slot] == dt)) {
      gaps_[slot] = dt;
      decays_[slot] = std::exp(s * dt);
    }
    return decays_[slot];
  }
  static std::size_t slot_of(double dt) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &dt, sizeof bits);
    return static_cast<std::size_t>((bits * 0x9E3779B97F4A7C15ull) >> 58);  // of 64
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

std::vector<std::vector<double>> ringing_sequences(std::span<const double> times_s, std::span<const double> inputs,
                                                   std::span<const RingingMode> modes) {
  std::vector<Pole> poles(modes.begin(), modes.end());
  std::vector<std::vector<double>> r(modes.size(), std::vector<double>(inputs.size(), 0.0));
  std::vector<std::complex<double>> sums(modes.size(), 0.0);
  for (std::size_t i = 1; i < inputs.size(); ++i) {
    const double dt = times_s[i] - times_s[i - 1], du = inputs[i] - inputs[i - 1];
    const std::size_t slot = Pole::slot_of(dt);
    for (std::size_t m = 0; m < poles.size(); ++m) {
      sums[m] = sums[m] * poles[m].decay(dt, slot) + poles[m].a * du;
      r[m][i] = sums[m].real();
    }
  }
  return r;
}

double torque_ringing_at(const InputHistory& history, const RingingMode& mode) {
  Pole pole(mode);
  const std::size_t i = history.index();
  const double t = history.at(i).time_s;
  const double memory_s = -std::log(kForgotten) / (-pole.s.real());
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
