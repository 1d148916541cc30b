#include "tests/diagnosis/campaign/anchor_baseline.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <numeric>
#include <numbers>

namespace gc::campaign {
namespace {

constexpr double kPi = std::numbers::pi;
using Eigen::Index;

// In-place radix-2 FFT.
void fft(std::vector<std::complex<double>>& a) {
  const std::size_t n = a.size();
  for (std::size_t i = 1, j = 0; i < n; ++i) {
    std::size_t bit = n >> 1;
    for (; j & bit; bit >>= 1) j ^= bit;
    j ^= bit;
    if (i < j) std::swap(a[i], a[j]);
  }
  for (std::size_t len = 2; len <= n; len <<= 1) {
    const double ang = -2 * kPi / static_cast<double>(len);
    const std::complex<double> wl(std::cos(ang), std::sin(ang));
    for (std::size_t i = 0; i < n; i += len) {
      std::complex<double> w(1.0);
      for (std::size_t k = 0; k < len / 2; ++k) {
        const auto u = a[i + k], v = a[i + k + len / 2] * w;
        a[i + k] = u + v;
        a[i + k + len / 2] = u - v;
        w *= wl;
      }
    }
  }
}

// Power of x at frequency f over times t (a single DFT term).
double power_at(const std::vector<double>& x, const std::vector<double>& t, double f) {
  double c = 0.0, s = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    c += x[i] * std::cos(2 * kPi * f * t[i]);
    s += x[i] * std::sin(2 * kPi * f * t[i]);
  }
  return c * c + s * s;
}

// The `count` largest periodogram peaks of x in [0.01, 4.9] Hz, each refined on a fine grid.
std::vector<double> peaks(std::vector<double> x, const std::vector<double>& t, int count) {
  const double mean = std::accumulate(x.begin(), x.end(), 0.0) / static_cast<double>(x.size());
  for (double& v : x) v -= mean;
  std::size_t n = 1;
  while (n < 2 * x.size()) n <<= 1;
  std::vector<std::complex<double>> a(n, 0.0);
  for (std::size_t i = 0; i < x.size(); ++i) a[i] = x[i];
  fft(a);
  const double df = kSampleRateHz / static_cast<double>(n);
  std::vector<std::pair<double, std::size_t>> local;
  for (std::size_t k = 2; k + 1 < n / 2; ++k) {
    const double f = k * df;
    if (f < 0.01 || f > 4.9) continue;
    const double p = std::norm(a[k]);
    if (p > std::norm(a[k - 1]) && p >= std::norm(a[k + 1])) local.push_back({p, k});
  }
  std::sort(local.rbegin(), local.rend());
  std::vector<double> out;
  for (const auto& [p, k] : local) {
    if (static_cast<int>(out.size()) == count) break;
    double best_f = k * df, best_p = 0.0;
    for (int s = -10; s <= 10; ++s) {
      const double f = (static_cast<double>(k) + s / 10.0) * df;
      const double q = power_at(x, t, f);
      if (q > best_p) best_p = q, best_f = f;
    }
    // Skip a peak within 3 bins of one kept (the same line).
    if (std::none_of(out.begin(), out.end(), [&](double g) { return std::abs(g - best_f) < 3 * df; })) {
      out.push_back(best_f);
    }
  }
  return out;
}

Eigen::MatrixXd library(const AnchorModel& a, const std::vector<InputRow>& in,
                        const std::vector<SensorMoments>& model, std::vector<std::string>* names) {
  const Index rows = static_cast<Index>(in.size());
  std::vector<Eigen::VectorXd> cols;
  std::vector<std::string> nm;
  auto add = [&](Eigen::VectorXd c, std::string n) {
    cols.push_back(std::move(c));
    nm.push_back(std::move(n));
  };
  const char* input_names[] = {"T", "zeta", "n", "temp"};
  Eigen::MatrixXd u(rows, 4);
  for (Index i = 0; i < rows; ++i) {
    const InputRow& r = in[static_cast<std::size_t>(i)];
    const double raw[] = {r.torque_nm, r.zeta_rad, r.speed_rpm, r.temperature_c};
    for (Index j = 0; j < 4; ++j) {
      const double span = std::max(1e-12, a.input_hi(j) - a.input_lo(j));
      u(i, j) = 2.0 * (raw[j] - a.input_lo(j)) / span - 1.0;
    }
  }
  add(Eigen::VectorXd::Ones(rows), "1");
  for (Index j = 0; j < 4; ++j) add(u.col(j), input_names[j]);
  for (Index j = 0; j < 4; ++j) {
    for (Index k = j; k < 4; ++k) add(u.col(j).cwiseProduct(u.col(k)), std::string(input_names[j]) + "*" + input_names[k]);
  }
  Eigen::VectorXd beta(rows), phase(rows), time(rows);
  for (Index i = 0; i < rows; ++i) {
    beta(i) = in[static_cast<std::size_t>(i)].beta_rad;
    phase(i) = in[static_cast<std::size_t>(i)].phase_rad;
    time(i) = in[static_cast<std::size_t>(i)].time_s;
  }
  for (int m = 1; m <= 2; ++m) {
    const Eigen::VectorXd s = (m * beta).array().sin().matrix(), c = (m * beta).array().cos().matrix();
    const std::string ms = m == 1 ? "beta" : "2beta";
    add(s, "sin(" + ms + ")");
    add(c, "cos(" + ms + ")");
    for (Index j = 0; j < 4; ++j) {
      add(s.cwiseProduct(u.col(j)), std::string(input_names[j]) + "*sin(" + ms + ")");
      add(c.cwiseProduct(u.col(j)), std::string(input_names[j]) + "*cos(" + ms + ")");
    }
  }
  for (int k = 1; k <= 4; ++k) {
    const Eigen::VectorXd s = (k * phase).array().sin().matrix(), c = (k * phase).array().cos().matrix();
    const std::string ks = std::to_string(k) + "phase";
    add(s, "sin(" + ks + ")");
    add(c, "cos(" + ks + ")");
    add(s.cwiseProduct(u.col(0)), "T*sin(" + ks + ")");
    add(c.cwiseProduct(u.col(0)), "T*cos(" + ks + ")");
  }
  Eigen::VectorXd my(rows), mz(rows);
  for (Index i = 0; i < rows; ++i) my(i) = model[static_cast<std::size_t>(i)].y_nm, mz(i) = model[static_cast<std::size_t>(i)].z_nm;
  auto lag = [&](const Eigen::VectorXd& v, Index l) {
    Eigen::VectorXd o(rows);
    for (Index i = 0; i < rows; ++i) o(i) = v(std::max<Index>(0, i - l));
    return o;
  };
  auto derivative = [&](const Eigen::VectorXd& v) {
    Eigen::VectorXd o(rows);
    for (Index i = 0; i < rows; ++i) {
      const Index lo = std::max<Index>(0, i - 1), hi = std::min<Index>(rows - 1, i + 1);
      o(i) = hi > lo ? (v(hi) - v(lo)) * kSampleRateHz / static_cast<double>(hi - lo) : 0.0;
    }
    return o;
  };
  add(my, "My");
  add(mz, "Mz");
  add(derivative(my), "dMy/dt");
  add(derivative(mz), "dMz/dt");
  for (Index l : {2, 4, 8, 16}) {
    add(lag(my, l), "My[-" + std::to_string(l) + "]");
    add(lag(mz, l), "Mz[-" + std::to_string(l) + "]");
  }
  for (double f : a.fourier_hz) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.4fHz", f);
    add((2 * kPi * f * time).array().sin().matrix(), std::string("sin(") + buf + ")");
    add((2 * kPi * f * time).array().cos().matrix(), std::string("cos(") + buf + ")");
  }
  Eigen::MatrixXd x(rows, static_cast<Index>(cols.size()));
  for (std::size_t c = 0; c < cols.size(); ++c) x.col(static_cast<Index>(c)) = cols[c];
  if (names) *names = nm;
  return x;
}

Eigen::VectorXd stlsq(const Eigen::MatrixXd& gram, const Eigen::VectorXd& xty, double ridge, double threshold) {
  const Index p = gram.rows();
  std::vector<Index> active(static_cast<std::size_t>(p));
  for (Index j = 0; j < p; ++j) active[static_cast<std::size_t>(j)] = j;
  Eigen::VectorXd coef = Eigen::VectorXd::Zero(p);
  for (int it = 0; it <= 10 && !active.empty(); ++it) {
    const Eigen::MatrixXd g = gram(active, active) + ridge * Eigen::MatrixXd::Identity(static_cast<Index>(active.size()), static_cast<Index>(active.size()));
    const Eigen::VectorXd sub = g.ldlt().solve(xty(active));
    coef.setZero();
    std::vector<Index> kept;
    for (std::size_t a = 0; a < active.size(); ++a) {
      coef(active[a]) = sub(static_cast<Index>(a));
      if (std::abs(sub(static_cast<Index>(a))) >= threshold) kept.push_back(active[a]);
    }
    if (kept.size() == active.size()) break;
    active = kept;
    if (active.empty()) coef.setZero();
  }
  return coef;
}

AnchorChannel fit_channel(const Eigen::MatrixXd& x, const Eigen::VectorXd& target) {
  const Index rows = x.rows();
  constexpr int kFolds = 5, kBlocks = 50, kThresholds = 25;
  const std::vector<double> ridges = {1e-6, 1e-4, 1e-3, 1e-2};
  const double spread = std::sqrt((target.array() - target.mean()).square().mean());
  std::vector<double> thresholds = {0.0};
  for (int k = 0; k < kThresholds; ++k) thresholds.push_back(spread * std::pow(10.0, -3.0 + 3.0 * k / (kThresholds - 1)));
  std::vector<Eigen::MatrixXd> mse(ridges.size(), Eigen::MatrixXd(static_cast<Index>(thresholds.size()), kFolds));
  for (int f = 0; f < kFolds; ++f) {
    std::vector<Index> train, test;
    for (Index i = 0; i < rows; ++i) ((i * kBlocks / rows) % kFolds == f ? test : train).push_back(i);
    const Eigen::MatrixXd xt = x(train, Eigen::all);
    const Eigen::MatrixXd gram = xt.transpose() * xt;
    const Eigen::VectorXd xty = xt.transpose() * target(train);
    const Eigen::MatrixXd xv = x(test, Eigen::all);
    const Eigen::VectorXd yv = target(test);
    for (std::size_t r = 0; r < ridges.size(); ++r) {
      for (std::size_t k = 0; k < thresholds.size(); ++k) {
        const Eigen::VectorXd c = stlsq(gram, xty, ridges[r] * static_cast<double>(train.size()), thresholds[k]);
        mse[r](static_cast<Index>(k), f) = (yv - xv * c).squaredNorm() / static_cast<double>(test.size());
      }
    }
  }
  std::size_t ridge = 0;
  Index best = 0;
  double best_mse = INFINITY;
  for (std::size_t r = 0; r < ridges.size(); ++r) {
    Index k = 0;
    const double m = mse[r].rowwise().mean().minCoeff(&k);
    if (m < best_mse) best_mse = m, ridge = r, best = k;
  }
  const Eigen::VectorXd mean = mse[ridge].rowwise().mean();
  const double sd = std::sqrt((mse[ridge].row(best).array() - mean(best)).square().sum() / (kFolds - 1));
  const double limit = mean(best) + sd / std::sqrt(static_cast<double>(kFolds));
  std::size_t chosen = static_cast<std::size_t>(best);
  for (std::size_t k = 0; k < thresholds.size(); ++k) {
    if (mean(static_cast<Index>(k)) <= limit && thresholds[k] > thresholds[chosen]) chosen = k;
  }
  AnchorChannel ch;
  ch.ridge = ridges[ridge];
  ch.threshold_nm = thresholds[chosen];
  ch.coefficients = stlsq(x.transpose() * x, x.transpose() * target, ch.ridge * static_cast<double>(rows), ch.threshold_nm);
  ch.active_terms = static_cast<int>((ch.coefficients.array() != 0.0).count());
  return ch;
}

Eigen::MatrixXd normalised(const AnchorModel& a, const std::vector<InputRow>& in, const std::vector<SensorMoments>& model) {
  const Eigen::MatrixXd x = library(a, in, model, nullptr);
  return (x.rowwise() - a.column_mean.transpose()).array().rowwise() / a.column_scale.transpose().array();
}

}  // namespace

AnchorModel fit_anchor(const std::vector<InputRow>& in, const std::vector<SensorMoments>& model,
                       const std::vector<SensorMoments>& measured) {
  AnchorModel a;
  std::vector<double> ry(in.size()), rz(in.size()), t(in.size());
  for (std::size_t i = 0; i < in.size(); ++i) {
    ry[i] = measured[i].y_nm - model[i].y_nm;
    rz[i] = measured[i].z_nm - model[i].z_nm;
    t[i] = in[i].time_s;
  }
  for (const auto& ch : {ry, rz}) {
    for (double f : peaks(ch, t, 3)) {
      if (std::none_of(a.fourier_hz.begin(), a.fourier_hz.end(), [&](double g) { return std::abs(g - f) < 1e-3; })) {
        a.fourier_hz.push_back(f);
      }
    }
  }
  a.input_lo = Eigen::VectorXd::Constant(4, INFINITY);
  a.input_hi = Eigen::VectorXd::Constant(4, -INFINITY);
  for (const InputRow& r : in) {
    const double raw[] = {r.torque_nm, r.zeta_rad, r.speed_rpm, r.temperature_c};
    for (Index j = 0; j < 4; ++j) a.input_lo(j) = std::min(a.input_lo(j), raw[j]), a.input_hi(j) = std::max(a.input_hi(j), raw[j]);
  }
  const Eigen::MatrixXd x = library(a, in, model, &a.terms);
  a.column_mean = x.colwise().mean();
  a.column_scale = (x.rowwise() - a.column_mean.transpose()).array().square().colwise().mean().sqrt();
  for (Index c = 0; c < x.cols(); ++c) {
    if (a.column_scale(c) < 1e-12) a.column_mean(c) = 0.0, a.column_scale(c) = 1.0;  // the constant stays 1
  }
  const Eigen::MatrixXd xn = (x.rowwise() - a.column_mean.transpose()).array().rowwise() / a.column_scale.transpose().array();
  a.y = fit_channel(xn, Eigen::Map<const Eigen::VectorXd>(ry.data(), static_cast<Index>(ry.size())));
  a.z = fit_channel(xn, Eigen::Map<const Eigen::VectorXd>(rz.data(), static_cast<Index>(rz.size())));
  return a;
}

std::vector<SensorMoments> predict_anchor(const AnchorModel& a, const std::vector<InputRow>& in,
                                          const std::vector<SensorMoments>& model) {
  const Eigen::MatrixXd x = normalised(a, in, model);
  const Eigen::VectorXd y = x * a.y.coefficients, z = x * a.z.coefficients;
  std::vector<SensorMoments> out(in.size());
  for (std::size_t i = 0; i < in.size(); ++i) {
    out[i] = {model[i].y_nm + y(static_cast<Index>(i)), model[i].z_nm + z(static_cast<Index>(i))};
  }
  return out;
}

std::string describe_anchor(const AnchorModel& a) {
  std::string s;
  for (const auto& [label, ch] : {std::pair{"y", &a.y}, std::pair{"z", &a.z}}) {
    s += std::string(s.empty() ? "" : "; ") + label + ": " + std::to_string(ch->active_terms) + " terms";
    std::vector<std::pair<double, std::string>> big;
    for (Index c = 0; c < ch->coefficients.size(); ++c) {
      if (ch->coefficients(c) != 0.0) big.push_back({std::abs(ch->coefficients(c)), a.terms[static_cast<std::size_t>(c)]});
    }
    std::sort(big.rbegin(), big.rend());
    for (std::size_t k = 0; k < std::min<std::size_t>(3, big.size()); ++k) s += (k ? ", " : " (") + big[k].second;
    if (!big.empty()) s += ")";
  }
  return s;
}

}  // namespace gc::campaign
