#include "tests/diagnosis/independent/sindy_baseline.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <stdexcept>

namespace gc::independent {
namespace {

// Raw inputs the library is built from, in a fixed order; speed and temperature only where every
// training sample has them.
struct RawInputs {
  std::vector<std::string> names;
  Eigen::MatrixXd values;  // rows x inputs
  Eigen::VectorXd beta;    // direction [rad], kept apart for the trigonometric terms
};

RawInputs raw_inputs(std::span<const MeasurementSample> in, bool speed, bool temperature) {
  RawInputs raw;
  raw.names = {"T", "zeta", "t"};
  if (speed) raw.names.push_back("speed");
  if (temperature) raw.names.push_back("temp");
  raw.values.resize(static_cast<Eigen::Index>(in.size()), static_cast<Eigen::Index>(raw.names.size()));
  raw.beta.resize(static_cast<Eigen::Index>(in.size()));
  for (std::size_t i = 0; i < in.size(); ++i) {
    const auto r = static_cast<Eigen::Index>(i);
    raw.values(r, 0) = in[i].torque_nm;
    raw.values(r, 1) = in[i].misalignment_rad;
    raw.values(r, 2) = in[i].time_s;
    Eigen::Index c = 3;
    if (speed) raw.values(r, c++) = in[i].speed_rpm.value_or(0.0);
    if (temperature) raw.values(r, c++) = in[i].temperature_c.value_or(0.0);
    raw.beta(r) = in[i].direction_rad;
  }
  return raw;
}

// Exponent vectors of every monomial in `variables` inputs of total degree <= max_degree.
std::vector<std::vector<int>> monomials(int variables, int max_degree) {
  std::vector<std::vector<int>> all;
  std::vector<int> e(static_cast<std::size_t>(variables), 0);
  std::function<void(int, int)> grow = [&](int var, int left) {
    if (var == variables) {
      all.push_back(e);
      return;
    }
    for (int k = 0; k <= left; ++k) {
      e[static_cast<std::size_t>(var)] = k;
      grow(var + 1, left - k);
    }
    e[static_cast<std::size_t>(var)] = 0;
  };
  grow(0, max_degree);
  std::stable_sort(all.begin(), all.end(), [](const auto& a, const auto& b) {
    int da = 0, db = 0;
    for (int x : a) da += x;
    for (int x : b) db += x;
    return da < db;
  });
  return all;
}

std::string monomial_name(const std::vector<int>& e, const std::vector<std::string>& names) {
  std::string s;
  for (std::size_t v = 0; v < e.size(); ++v) {
    for (int k = 0; k < e[v]; ++k) s += (s.empty() ? "" : "*") + names[v];
  }
  return s.empty() ? "1" : s;
}

// The library on scaled inputs u in [-1, 1]: monomials of degree <= max_degree, then each trig
// function of beta times the monomials of degree <= trig_product_degree.
Eigen::MatrixXd library(const Eigen::MatrixXd& u, const Eigen::VectorXd& beta, const SindySettings& s,
                        const std::vector<std::string>& names, std::vector<std::string>* terms) {
  const int variables = static_cast<int>(u.cols());
  const auto poly = monomials(variables, s.max_degree);
  const auto low = monomials(variables, s.trig_product_degree);
  const Eigen::Index rows = u.rows();
  const auto column_of = [&](const std::vector<int>& e) {
    Eigen::VectorXd c = Eigen::VectorXd::Ones(rows);
    for (int v = 0; v < variables; ++v) {
      for (int k = 0; k < e[static_cast<std::size_t>(v)]; ++k) c = c.cwiseProduct(u.col(v));
    }
    return c;
  };
  const std::vector<std::pair<std::string, Eigen::VectorXd>> trig = {
      {"sin(beta)", beta.array().sin().matrix()}, {"cos(beta)", beta.array().cos().matrix()},
      {"sin(2beta)", (2.0 * beta).array().sin().matrix()}, {"cos(2beta)", (2.0 * beta).array().cos().matrix()}};
  Eigen::MatrixXd x(rows, static_cast<Eigen::Index>(poly.size() + trig.size() * low.size()));
  Eigen::Index c = 0;
  if (terms) terms->clear();
  for (const auto& e : poly) {
    x.col(c++) = column_of(e);
    if (terms) terms->push_back(monomial_name(e, names));
  }
  for (const auto& [trig_name, t] : trig) {
    for (const auto& e : low) {
      x.col(c++) = column_of(e).cwiseProduct(t);
      if (terms) terms->push_back(monomial_name(e, names) == "1" ? trig_name : monomial_name(e, names) + "*" + trig_name);
    }
  }
  return x;
}

// Sequentially thresholded ridge least squares on the Gram matrix of the chosen rows: fit, drop
// every coefficient below `threshold` in size, refit on the rest, until the set stops changing.
Eigen::VectorXd stlsq(const Eigen::MatrixXd& gram, const Eigen::VectorXd& xty, double ridge, double threshold,
                      int iterations) {
  const Eigen::Index p = gram.rows();
  std::vector<Eigen::Index> active(static_cast<std::size_t>(p));
  for (Eigen::Index j = 0; j < p; ++j) active[static_cast<std::size_t>(j)] = j;
  Eigen::VectorXd coef = Eigen::VectorXd::Zero(p);
  for (int it = 0; it <= iterations && !active.empty(); ++it) {
    const auto n = static_cast<Eigen::Index>(active.size());
    Eigen::MatrixXd g(n, n);
    Eigen::VectorXd b(n);
    for (Eigen::Index a = 0; a < n; ++a) {
      b(a) = xty(active[static_cast<std::size_t>(a)]);
      for (Eigen::Index c = 0; c < n; ++c) g(a, c) = gram(active[static_cast<std::size_t>(a)], active[static_cast<std::size_t>(c)]);
      g(a, a) += ridge;
    }
    const Eigen::VectorXd sub = g.ldlt().solve(b);
    coef.setZero();
    std::vector<Eigen::Index> kept;
    for (Eigen::Index a = 0; a < n; ++a) {
      if (std::abs(sub(a)) >= threshold) kept.push_back(active[static_cast<std::size_t>(a)]);
      coef(active[static_cast<std::size_t>(a)]) = sub(a);
    }
    if (kept.size() == active.size()) break;
    active = kept;
    if (active.empty()) coef.setZero();
  }
  return coef;
}

SindyChannel fit_channel(const Eigen::MatrixXd& x, const Eigen::VectorXd& target, const SindySettings& s) {
  const Eigen::Index rows = x.rows();
  const double spread = std::sqrt((target.array() - target.mean()).square().mean());
  std::vector<double> thresholds = {0.0};
  for (int k = 0; k < s.thresholds; ++k) {
    thresholds.push_back(spread * std::pow(10.0, -3.0 + 3.0 * k / std::max(1, s.thresholds - 1)));
  }
  // Fold of each row: contiguous blocks in time, dealt to the folds in turn, so that correlated
  // neighbours stay on one side and every fold spans the whole sequence.
  std::vector<int> fold(static_cast<std::size_t>(rows));
  for (Eigen::Index i = 0; i < rows; ++i) {
    const auto block = static_cast<int>(i * s.blocks / rows);
    fold[static_cast<std::size_t>(i)] = block % s.folds;
  }
  // fold_mse[r](k, f): held-out mean square of fold f at ridge r and threshold k.
  std::vector<Eigen::MatrixXd> fold_mse(s.ridges.size(),
                                        Eigen::MatrixXd(static_cast<Eigen::Index>(thresholds.size()), s.folds));
  for (int f = 0; f < s.folds; ++f) {
    std::vector<Eigen::Index> train, test;
    for (Eigen::Index i = 0; i < rows; ++i) (fold[static_cast<std::size_t>(i)] == f ? test : train).push_back(i);
    const Eigen::MatrixXd xt = x(train, Eigen::all);
    const Eigen::MatrixXd gram = xt.transpose() * xt;
    const Eigen::VectorXd xty = xt.transpose() * target(train);
    const Eigen::MatrixXd xv = x(test, Eigen::all);
    const Eigen::VectorXd yv = target(test);
    for (std::size_t r = 0; r < s.ridges.size(); ++r) {
      for (std::size_t k = 0; k < thresholds.size(); ++k) {
        const Eigen::VectorXd coef =
            stlsq(gram, xty, s.ridges[r] * static_cast<double>(train.size()), thresholds[k], s.stlsq_iterations);
        fold_mse[r](static_cast<Eigen::Index>(k), f) = (yv - xv * coef).squaredNorm() / static_cast<double>(test.size());
      }
    }
  }
  // The ridge with the lowest cross-validated error at its best threshold; then the one-standard-
  // error rule on the threshold: the largest (sparsest) whose mean held-out error is within one
  // standard error (over folds) of that best.
  std::size_t ridge = 0;
  Eigen::Index best = 0;
  double best_mse = INFINITY;
  for (std::size_t r = 0; r < s.ridges.size(); ++r) {
    Eigen::Index k = 0;
    const double m = fold_mse[r].rowwise().mean().minCoeff(&k);
    if (m < best_mse) best_mse = m, ridge = r, best = k;
  }
  const Eigen::VectorXd mean = fold_mse[ridge].rowwise().mean();
  const double sd = std::sqrt((fold_mse[ridge].row(best).array() - mean(best)).square().sum() / (s.folds - 1));
  const double limit = mean(best) + sd / std::sqrt(static_cast<double>(s.folds));
  std::size_t chosen = static_cast<std::size_t>(best);
  for (std::size_t k = 0; k < thresholds.size(); ++k) {
    if (mean(static_cast<Eigen::Index>(k)) <= limit && thresholds[k] > thresholds[chosen]) chosen = k;
  }
  SindyChannel channel;
  channel.ridge = s.ridges[ridge];
  channel.threshold_nm = thresholds[chosen];
  channel.cv_rmse_nm = std::sqrt(mean(static_cast<Eigen::Index>(chosen)));
  channel.coefficients = stlsq(x.transpose() * x, x.transpose() * target, channel.ridge * static_cast<double>(rows),
                               channel.threshold_nm, s.stlsq_iterations);
  channel.active_terms = static_cast<int>((channel.coefficients.array() != 0.0).count());
  return channel;
}

Eigen::MatrixXd normalised_library(const SindyModel& m, std::span<const MeasurementSample> inputs,
                                   const SindySettings& s, std::vector<std::string>* terms) {
  const RawInputs raw = raw_inputs(inputs, m.uses_speed, m.uses_temperature);
  const Eigen::MatrixXd u =
      (raw.values.rowwise() - m.input_offset.transpose()).array().rowwise() / m.input_scale.transpose().array();
  const Eigen::MatrixXd x = library(u, raw.beta, s, raw.names, terms);
  if (m.column_mean.size() == 0) return x;
  return (x.rowwise() - m.column_mean.transpose()).array().rowwise() / m.column_scale.transpose().array();
}

}  // namespace

SindyModel fit_sindy(std::span<const MeasurementSample> inputs, std::span<const SensorMoments> residual,
                     const SindySettings& settings) {
  if (inputs.size() != residual.size() || inputs.size() < static_cast<std::size_t>(4 * settings.blocks)) {
    throw std::invalid_argument("fit_sindy: inputs and residual must be equal and long enough");
  }
  SindyModel m;
  m.settings = settings;
  m.uses_speed = std::all_of(inputs.begin(), inputs.end(), [](const auto& s) { return s.speed_rpm.has_value(); });
  m.uses_temperature = std::all_of(inputs.begin(), inputs.end(), [](const auto& s) { return s.temperature_c.has_value(); });
  const RawInputs raw = raw_inputs(inputs, m.uses_speed, m.uses_temperature);
  // Inputs to [-1, 1] before the monomials are formed, so that T^3 and zeta^3 stay conditioned.
  const Eigen::VectorXd lo = raw.values.colwise().minCoeff(), hi = raw.values.colwise().maxCoeff();
  m.input_offset = 0.5 * (lo + hi);
  m.input_scale = (0.5 * (hi - lo)).cwiseMax(1e-12);
  const Eigen::MatrixXd x = normalised_library(m, inputs, settings, &m.terms);
  // Columns to zero mean and unit variance, so that one threshold [N·m] fits every term; the
  // constant column stays 1 (it carries the mean).
  m.column_mean = x.colwise().mean();
  m.column_scale = ((x.rowwise() - m.column_mean.transpose()).array().square().colwise().mean()).sqrt();
  for (Eigen::Index c = 0; c < x.cols(); ++c) {
    if (m.column_scale(c) < 1e-12) {
      m.column_mean(c) = 0.0;
      m.column_scale(c) = 1.0;
    }
  }
  const Eigen::MatrixXd xn = (x.rowwise() - m.column_mean.transpose()).array().rowwise() / m.column_scale.transpose().array();
  Eigen::VectorXd ry(static_cast<Eigen::Index>(residual.size())), rz(ry.size());
  for (std::size_t i = 0; i < residual.size(); ++i) {
    ry(static_cast<Eigen::Index>(i)) = residual[i].y_nm;
    rz(static_cast<Eigen::Index>(i)) = residual[i].z_nm;
  }
  m.y = fit_channel(xn, ry, settings);
  m.z = fit_channel(xn, rz, settings);
  return m;
}

std::vector<SensorMoments> predict_sindy(const SindyModel& model, std::span<const MeasurementSample> inputs) {
  const Eigen::MatrixXd x = normalised_library(model, inputs, model.settings, nullptr);
  const Eigen::VectorXd y = x * model.y.coefficients, z = x * model.z.coefficients;
  std::vector<SensorMoments> out(inputs.size());
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    out[i] = {y(static_cast<Eigen::Index>(i)), z(static_cast<Eigen::Index>(i))};
  }
  return out;
}

}  // namespace gc::independent
