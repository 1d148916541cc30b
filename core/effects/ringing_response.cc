#include "core/effects/ringing_response.h"

#include <cmath>
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
  /// e^{s dt}, recomputed only when the gap changes (a uniform sampling costs one exp).
  std::complex<double> decay(double dt) {
    if (dt != last_dt_) { last_dt_ = dt; last_ = std::exp(s * dt); }
    return last_;
  }

 private:
  double last_dt_ = -1.0;
  std::complex<double> last_;
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
