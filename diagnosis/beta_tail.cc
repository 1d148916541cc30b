#include "diagnosis/beta_tail.h"

#include <algorithm>
#include <cmath>

namespace gc {
namespace {

/// log Gamma(x) without the global sign that std::lgamma writes (glibc's lgamma_r).
double log_gamma(double x) {
  int sign = 0;
  return ::lgamma_r(x, &sign);
}

/// The continued fraction of I_x(a, b) (Numerical Recipes 6.4), converging for x < (a + 1) / (a + b + 2).
double beta_fraction(double x, double a, double b) {
  constexpr double kTiny = 1e-300, kEpsilon = 1e-15;
  double c = 1.0, d = 1.0 - (a + b) * x / (a + 1.0);
  if (std::abs(d) < kTiny) d = kTiny;
  d = 1.0 / d;
  double h = d;
  for (int m = 1; m <= 500; ++m) {
    const double m2 = 2.0 * m;
    double aa = m * (b - m) * x / ((a - 1.0 + m2) * (a + m2));
    d = 1.0 + aa * d;
    c = 1.0 + aa / c;
    if (std::abs(d) < kTiny) d = kTiny;
    if (std::abs(c) < kTiny) c = kTiny;
    d = 1.0 / d;
    h *= d * c;
    aa = -(a + m) * (a + b + m) * x / ((a + m2) * (a + 1.0 + m2));
    d = 1.0 + aa * d;
    c = 1.0 + aa / c;
    if (std::abs(d) < kTiny) d = kTiny;
    if (std::abs(c) < kTiny) c = kTiny;
    d = 1.0 / d;
    const double step = d * c;
    h *= step;
    if (std::abs(step - 1.0) < kEpsilon) break;
  }
  return h;
}

}  // namespace

double regularized_incomplete_beta(double x, double a, double b) {
  if (!(x > 0.0)) return 0.0;
  if (!(x < 1.0)) return 1.0;
  const double front = std::exp(log_gamma(a + b) - log_gamma(a) - log_gamma(b) + a * std::log(x) + b * std::log1p(-x));
  if (x < (a + 1.0) / (a + b + 2.0)) return std::clamp(front * beta_fraction(x, a, b) / a, 0.0, 1.0);
  return std::clamp(1.0 - front * beta_fraction(1.0 - x, b, a) / b, 0.0, 1.0);
}

double beta_upper_tail(double observed, double mean, double variance) {
  if (!(observed > mean) || !(mean > 0.0) || !(mean < 1.0)) return 1.0;
  if (!(observed < 1.0)) return 0.0;
  const double spread = mean * (1.0 - mean);
  if (!(variance > 0.0) || !(variance < spread)) return variance > 0.0 ? 1.0 : 0.0;
  const double common = spread / variance - 1.0;  // a + b
  return 1.0 - regularized_incomplete_beta(observed, mean * common, (1.0 - mean) * common);
}

}  // namespace gc
