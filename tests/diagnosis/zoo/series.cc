#include "tests/diagnosis/zoo/series.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "tests/diagnosis/zoo/channels.h"

namespace gc::zoo {

MeasurementSample Channels::sample(std::size_t i) const {
  MeasurementSample s;
  s.time_s = time_s[i];
  s.torque_nm = torque_nm[i];
  s.misalignment_rad = zeta_rad[i];
  s.direction_rad = beta_rad[i];
  s.speed_rpm = speed_rpm[i];
  s.temperature_c = temperature_c[i];
  return s;
}

void Channels::resize(std::size_t n) {
  for (auto* v : {&time_s, &torque_nm, &zeta_rad, &beta_rad, &speed_rpm, &temperature_c, &msy_nm, &msz_nm}) v->resize(n);
}

double mean(const Series& x) {
  if (x.empty()) return 0.0;
  double s = 0.0;
  for (double v : x) s += v;
  return s / static_cast<double>(x.size());
}

double rms_about_mean(const Series& x) {
  if (x.empty()) return 0.0;
  const double m = mean(x);
  double s = 0.0;
  for (double v : x) s += (v - m) * (v - m);
  return std::sqrt(s / static_cast<double>(x.size()));
}

void scale_to(Series& x, double rms) {
  const double m = mean(x), r = rms_about_mean(x);
  for (double& v : x) v = r > 0.0 ? (v - m) * rms / r : 0.0;
}

Series white(std::size_t n, Rng& rng) {
  Series x(n);
  for (double& v : x) v = rng.normal();
  return x;
}

Series ar1(std::size_t n, double phi, Rng& rng) {
  Series x(n);
  const double s = std::sqrt(1.0 - phi * phi);
  double v = rng.normal();
  for (std::size_t i = 0; i < n; ++i) {
    if (i > 0) v = phi * v + s * rng.normal();
    x[i] = v;
  }
  return x;
}

Series ar2_resonant(std::size_t n, double f, double r, Rng& rng) {
  const double a1 = 2.0 * r * std::cos(2.0 * std::numbers::pi * f), a2 = -r * r;
  Series x(n);
  double x1 = 0.0, x2 = 0.0;
  // Burn-in of a few memory lengths so that the record starts stationary.
  const auto burn = static_cast<std::size_t>(std::min(2.0e5, 10.0 / std::max(1e-6, 1.0 - r)));
  for (std::size_t i = 0; i < burn + n; ++i) {
    const double v = a1 * x1 + a2 * x2 + rng.normal();
    x2 = x1;
    x1 = v;
    if (i >= burn) x[i - burn] = v;
  }
  return x;
}

Series pink(std::size_t n, Rng& rng) {
  Series x(n, 0.0);
  for (double tau = 1.0; tau < 2.0 * static_cast<double>(n); tau *= 2.0) {
    const Series c = ar1(n, std::exp(-1.0 / tau), rng);
    for (std::size_t i = 0; i < n; ++i) x[i] += c[i];
  }
  return x;
}

Series brown(std::size_t n, Rng& rng) {
  Series x(n);
  double v = 0.0;
  for (double& e : x) e = (v += rng.normal());
  return x;
}

namespace {
Series biquad(const Series& x, double b0, double b1, double b2, double a0, double a1, double a2) {
  Series y(x.size());
  double x1 = 0, x2 = 0, y1 = 0, y2 = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double v = (b0 * x[i] + b1 * x1 + b2 * x2 - a1 * y1 - a2 * y2) / a0;
    x2 = x1, x1 = x[i], y2 = y1, y1 = v;
    y[i] = v;
  }
  return y;
}
}  // namespace

Series lowpass2(const Series& x, double f, double q) {
  const double w = 2.0 * std::numbers::pi * f, c = std::cos(w), alpha = std::sin(w) / (2.0 * q);
  return biquad(x, (1 - c) / 2, 1 - c, (1 - c) / 2, 1 + alpha, -2 * c, 1 - alpha);
}

Series bandpass2(const Series& x, double f, double q) {
  const double w = 2.0 * std::numbers::pi * f, c = std::cos(w), alpha = std::sin(w) / (2.0 * q);
  return biquad(x, alpha, 0.0, -alpha, 1 + alpha, -2 * c, 1 - alpha);
}

Series moving_average(const Series& x, std::size_t m) {
  return varying_average(x, std::vector<double>(x.size(), static_cast<double>(std::max<std::size_t>(1, m))));
}

Series varying_average(const Series& x, const std::vector<double>& window) {
  std::vector<double> prefix(x.size() + 1, 0.0);
  for (std::size_t i = 0; i < x.size(); ++i) prefix[i + 1] = prefix[i] + x[i];
  Series y(x.size());
  for (std::size_t i = 0; i < x.size(); ++i) {
    const auto m = static_cast<std::size_t>(std::clamp(std::lround(window[i]), 1L, static_cast<long>(i + 1)));
    y[i] = (prefix[i + 1] - prefix[i + 1 - m]) / static_cast<double>(m);
  }
  return y;
}

}  // namespace gc::zoo
