#include "tests/diagnosis/zoo/oracle.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>

namespace gc::zoo {
namespace {

std::vector<double> demeaned(const std::vector<double>& x) {
  const double mean = std::accumulate(x.begin(), x.end(), 0.0) / static_cast<double>(x.size());
  std::vector<double> y(x.size());
  std::transform(x.begin(), x.end(), y.begin(), [mean](double v) { return v - mean; });
  return y;
}

// Burg's recursion (mean removed) to max_order; at each order m, visit(m, a, e) with the
// coefficients and the innovations' variance of the order-m fit.
template <class Visit>
void burg_recursion(const std::vector<double>& x, int max_order, Visit visit) {
  const std::vector<double> v = demeaned(x);
  const std::size_t n = v.size();
  std::vector<double> f(v), b(v), a{};
  double e = std::inner_product(v.begin(), v.end(), v.begin(), 0.0) / static_cast<double>(n);
  visit(0, a, e);
  for (int m = 1; m <= max_order; ++m) {
    // The reflection coefficient from the forward and backward errors of order m-1.
    double num = 0.0, den = 0.0;
    for (std::size_t t = static_cast<std::size_t>(m); t < n; ++t) {
      num += f[t] * b[t - 1];
      den += f[t] * f[t] + b[t - 1] * b[t - 1];
    }
    if (den <= 0.0) return;
    const double k = -2.0 * num / den;
    std::vector<double> next(a.size() + 1);
    for (std::size_t j = 0; j < a.size(); ++j) next[j] = a[j] + k * a[a.size() - 1 - j];
    next.back() = k;
    a = std::move(next);
    for (std::size_t t = n - 1; t >= static_cast<std::size_t>(m); --t) {
      const double ft = f[t];
      f[t] = ft + k * b[t - 1];
      b[t] = b[t - 1] + k * ft;
    }
    e *= (1.0 - k * k);
    visit(m, a, e);
  }
}

Autoregression burg_by_aic(const std::vector<double>& x, int max_order) {
  Autoregression best;
  double best_aic = INFINITY;
  const double n = static_cast<double>(x.size());
  burg_recursion(x, max_order, [&](int m, const std::vector<double>& a, double e) {
    const double aic = n * std::log(std::max(e, 1e-300)) + 2.0 * m;
    if (aic < best_aic) best_aic = aic, best = {a, e};
  });
  return best;
}

// x filtered by x_t + sum_j a_j x_{t-j}, for t >= from (from >= a.size()), into out.
void whitened_into(const std::vector<double>& x, const std::vector<double>& a, std::size_t from, double* out) {
  for (std::size_t t = from; t < x.size(); ++t) {
    double v = x[t];
    for (std::size_t j = 0; j < a.size(); ++j) v += a[j] * x[t - 1 - j];
    *out++ = v;
  }
}

Autoregression fitted(const std::vector<double>& noise) {
  return burg_by_aic(noise, static_cast<int>(std::min<std::size_t>(64, noise.size() / 10)));
}

}  // namespace

Autoregression burg(const std::vector<double>& x, int order) {
  if (order < 0 || x.size() < static_cast<std::size_t>(order) + 2) throw std::invalid_argument("burg: too few samples");
  Autoregression fit;
  burg_recursion(x, order, [&](int, const std::vector<double>& a, double e) { fit = {a, e}; });
  return fit;
}

Whitening::Whitening(const std::vector<double>& noise_y, const std::vector<double>& noise_z)
    : ar_y_(fitted(noise_y)), ar_z_(fitted(noise_z)), from_(std::max(ar_y_.a.size(), ar_z_.a.size())), n_(noise_y.size()) {
  if (noise_z.size() != n_ || n_ <= from_) return;
  const std::size_t m = n_ - from_;
  std::vector<double> ey(m), ez(m);
  whitened_into(demeaned(noise_y), ar_y_.a, from_, ey.data());
  whitened_into(demeaned(noise_z), ar_z_.a, from_, ez.data());
  // The innovations' covariance between the channels at lag 0 (a common-mode noise): the signal
  // that parts the channels where their noises move together is told apart better.
  const double mm = static_cast<double>(m);
  const double cyy = std::inner_product(ey.begin(), ey.end(), ey.begin(), 0.0) / mm;
  const double czz = std::inner_product(ez.begin(), ez.end(), ez.begin(), 0.0) / mm;
  double cyz = std::inner_product(ey.begin(), ey.end(), ez.begin(), 0.0) / mm;
  if (!(cyy > 0.0 && czz > 0.0)) return;  // a channel without noise
  if (cyz * cyz > 0.999 * cyy * czz) cyz = std::copysign(std::sqrt(0.999 * cyy * czz), cyz);
  sy_ = 1.0 / std::sqrt(cyy);
  rho_ = cyz / cyy;
  sz_ = 1.0 / std::sqrt((cyy * czz - cyz * cyz) / cyy);
  ok_ = true;
}

void Whitening::apply(const std::vector<double>& y, const std::vector<double>& z, std::vector<double>& out) const {
  const std::size_t m = n_ - from_;
  out.resize(2 * m);
  whitened_into(y, ar_y_.a, from_, out.data());
  whitened_into(z, ar_z_.a, from_, out.data() + m);
  for (std::size_t t = 0; t < m; ++t) {
    const double ey = out[t], ez = out[m + t];
    out[t] = sy_ * ey;
    out[m + t] = sz_ * (ez - rho_ * ey);
  }
}

double power_at_one_percent(double d) {
  constexpr double z_01 = 2.3263478740408408;  // Phi^-1(0.99)
  return 0.5 * std::erfc(-(d - z_01) / std::sqrt(2.0));
}

void check_signal_and_noise(const std::string& who, const std::vector<double>& signal_y, const std::vector<double>& signal_z,
                            const std::vector<double>& noise_y, const std::vector<double>& noise_z) {
  const std::size_t n = signal_y.size();
  if (n < 64 || signal_z.size() != n || noise_y.size() != n || noise_z.size() != n)
    throw std::invalid_argument(who + ": four series of one length >= 64");
  for (const auto* v : {&signal_y, &signal_z, &noise_y, &noise_z})
    if (!std::all_of(v->begin(), v->end(), [](double x) { return std::isfinite(x); }))
      throw std::invalid_argument(who + ": a value not finite");
}

OracleBound oracle_bound(const std::vector<double>& signal_y, const std::vector<double>& signal_z,
                         const std::vector<double>& noise_y, const std::vector<double>& noise_z) {
  check_signal_and_noise("oracle_bound", signal_y, signal_z, noise_y, noise_z);
  OracleBound bound;
  const Whitening whitening(noise_y, noise_z);
  bound.order_y = whitening.order_y();
  bound.order_z = whitening.order_z();
  if (!whitening.ok()) {  // a channel without noise: no bound
    bound.d = bound.power = std::numeric_limits<double>::quiet_NaN();
    return bound;
  }
  std::vector<double> w;
  whitening.apply(signal_y, signal_z, w);
  bound.d = std::sqrt(std::inner_product(w.begin(), w.end(), w.begin(), 0.0));
  bound.power = power_at_one_percent(bound.d);
  return bound;
}

}  // namespace gc::zoo
