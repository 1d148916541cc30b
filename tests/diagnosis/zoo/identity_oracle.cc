#include "tests/diagnosis/zoo/identity_oracle.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numeric>
#include <regex>
#include <stdexcept>

#include <Eigen/Dense>

#include "tests/diagnosis/zoo/oracle.h"
#include "tests/diagnosis/zoo/rng.h"

namespace gc::zoo {
namespace {

double squared(const std::vector<double>& v) { return std::inner_product(v.begin(), v.end(), v.begin(), 0.0); }

// The nearest member of one family to the whitened target (identity_oracle.h): start points ranked
// by their shape, refined by Levenberg-Marquardt (robust, then plain) in coordinates scaled by each
// parameter's range, the nearest polished by an evolution strategy. The answer is the least
// distance of ANY member evaluated on the way (a member's distance is exact; only the search is
// not), so whatever the search misses can only make d_F larger.
class Fit {
 public:
  Fit(const Whitening& w, const std::vector<double>& target, const SignalFamily& f, std::size_t rows, const IdentityOptions& o)
      : w_(w), target_(target), f_(f), rows_(rows), o_(o) {
    for (std::size_t j = 0; j < f.parameters.size(); ++j) {
      const EffectParameter& p = f.parameters[j];
      if (p.lo < p.hi) free_.push_back(j);
    }
  }

  // The least squared distance found and its theta.
  std::pair<double, std::vector<double>> run() {
    std::vector<double> held = f_.none;
    if (held.size() != f_.parameters.size()) {
      held.assign(f_.parameters.size(), 0.0);
      for (std::size_t j = 0; j < held.size(); ++j) held[j] = std::clamp(0.0, f_.parameters[j].lo, f_.parameters[j].hi);
    }
    struct Start {
      double rank, f;
      std::vector<double> theta, w;
    };
    std::vector<Start> starts;
    std::vector<double> w, w2;
    std::vector<std::size_t> sizes;
    for (int j : f_.size_parameters) {
      if (j >= 0 && std::find(free_.begin(), free_.end(), static_cast<std::size_t>(j)) != free_.end()) sizes.push_back(static_cast<std::size_t>(j));
    }
    // With a size parameter, a start is moved to the multiple of its size that is nearest for
    // its signal scaled (where that is nearer). Its rank: the sum of its smallest 80 % of squared
    // whitened residuals (the rows where a step of int(qN/4) falls on one side only left out, so
    // that the smooth part of the change, its shape, ranks it).
    auto consider = [&](std::vector<double> theta) {
      double f = value(theta, w);
      const double ww = squared(w);
      if (!sizes.empty() && std::isfinite(f) && ww > 0.0) {
        const double c = std::inner_product(w.begin(), w.end(), target_.begin(), 0.0);
        std::vector<double> th = theta;
        for (std::size_t j : sizes) th[j] *= c / ww;
        inside(th);
        const double f2 = value(th, w2);
        if (f2 < f) f = f2, theta = std::move(th), std::swap(w, w2);
      }
      starts.push_back({std::isfinite(f) ? trimmed(w) : INFINITY, f, std::move(theta), w});
    };
    consider(held);
    if (free_.empty()) return {best_f_, best_theta_};
    Rng rng(derive_seed(o_.seed, f_.name));
    for (int s = 0; s < o_.starts; ++s) {
      std::vector<double> theta = held;
      for (std::size_t j : free_) {
        const EffectParameter& p = f_.parameters[j];
        const bool lo = std::isfinite(p.lo), hi = std::isfinite(p.hi);
        const double a = lo ? p.lo : hi ? p.hi - 2.0 * p.scale : -p.scale;
        const double b = hi ? p.hi : lo ? p.lo + 2.0 * p.scale : p.scale;
        theta[j] = rng.uniform(a, b);
      }
      inside(theta);
      consider(std::move(theta));
    }
    // Refined: the best `refined` by rank (shape) and the best `refined` by distance, each once.
    std::vector<std::size_t> by_rank(starts.size()), by_value(starts.size()), chosen;
    std::iota(by_rank.begin(), by_rank.end(), 0);
    std::iota(by_value.begin(), by_value.end(), 0);
    std::stable_sort(by_rank.begin(), by_rank.end(), [&](std::size_t a, std::size_t b) { return starts[a].rank < starts[b].rank; });
    std::stable_sort(by_value.begin(), by_value.end(), [&](std::size_t a, std::size_t b) { return starts[a].f < starts[b].f; });
    for (int r = 0; r < o_.refined && r < static_cast<int>(starts.size()); ++r) {
      for (std::size_t k : {by_rank[r], by_value[r]}) {
        if (std::find(chosen.begin(), chosen.end(), k) == chosen.end() && std::isfinite(starts[k].f)) chosen.push_back(k);
      }
    }
    for (std::size_t k : chosen) {
      auto [theta, wk] = refine(starts[k].theta, starts[k].w, true);
      refine(std::move(theta), std::move(wk), false);
    }
    // The evolution strategy twice from the nearest member seen (a restart at its first step size
    // leaves a cusp that is not the nearest).
    for (std::uint64_t stream = 0; stream < 2 && std::isfinite(best_f_); ++stream) polish(best_theta_, best_f_, stream);
    return {best_f_, best_theta_};
  }

  int evaluations() const { return evaluations_; }

 private:
  double unit(std::size_t j) const {
    const EffectParameter& p = f_.parameters[j];
    return std::isfinite(p.lo) && std::isfinite(p.hi) ? p.hi - p.lo : p.scale;
  }

  void inside(std::vector<double>& theta) const {
    for (std::size_t j = 0; j < theta.size(); ++j) theta[j] = std::clamp(theta[j], f_.parameters[j].lo, f_.parameters[j].hi);
    if (f_.project) f_.project(theta);
  }

  double distance(const std::vector<double>& w) const {
    double f = 0.0;
    for (std::size_t t = 0; t < w.size(); ++t) f += (target_[t] - w[t]) * (target_[t] - w[t]);
    return std::isfinite(f) ? f : INFINITY;
  }

  // The squared distance at theta (infinite where the signal is not finite); w the whitened
  // signal. The nearest member seen is kept.
  double value(const std::vector<double>& theta, std::vector<double>& w) {
    ++evaluations_;
    f_.signal(theta, y_, z_);
    if (y_.size() != rows_ || z_.size() != rows_) throw std::logic_error("identity oracle: a family's signal of another length");
    w_.apply(y_, z_, w);
    const double f = distance(w);
    if (f < best_f_) best_f_ = f, best_theta_ = theta;
    return f;
  }

  // The sum of the smallest 80 % of the squared residuals against w.
  double trimmed(const std::vector<double>& w) const {
    std::vector<double> e(w.size());
    for (std::size_t t = 0; t < w.size(); ++t) e[t] = (target_[t] - w[t]) * (target_[t] - w[t]);
    auto keep = e.begin() + static_cast<std::ptrdiff_t>(e.size() * 4 / 5);
    std::nth_element(e.begin(), keep, e.end());
    return std::accumulate(e.begin(), keep, 0.0);
  }

  static double median(std::vector<double> v) {
    if (v.empty()) return 0.0;
    auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
    std::nth_element(v.begin(), mid, v.end());
    return *mid;
  }

  // Levenberg-Marquardt from theta (w its whitened signal): forward-difference Jacobians in the
  // scaled coordinates. Robust: the rows weighted as in a Huber fit (residual beyond 2.5 robust
  // sigmas, or a Jacobian row beyond 10 times the median's: a step of int(qN/4) crossed by one
  // side or by a difference's increment), so the smooth part of the change sets theta, where the
  // steps then coincide when the member is the same physics; a step accepted where the weighted
  // loss falls. Plain: least squares. Returns the last theta and its whitened signal.
  std::pair<std::vector<double>, std::vector<double>> refine(std::vector<double> theta, std::vector<double> w, bool robust) {
    const std::size_t p = free_.size(), m = target_.size();
    Eigen::MatrixXd jac(m, p);
    Eigen::VectorXd r(m), weight = Eigen::VectorXd::Ones(m);
    std::vector<double> wh;
    double mu = 1e-3;
    double diff = 1e-2;  // the differences' increment in the scaled coordinates
    for (int it = 0; it < o_.iterations; ++it) {
      for (std::size_t t = 0; t < m; ++t) r(static_cast<Eigen::Index>(t)) = target_[t] - w[t];
      if (r.squaredNorm() == 0.0) break;
      bool finite = true;
      for (std::size_t c = 0; c < p && finite; ++c) {
        const std::size_t j = free_[c];
        double h = diff * unit(j);
        std::vector<double> th = theta;
        th[j] += h;
        if (th[j] > f_.parameters[j].hi) th[j] = theta[j] - h, h = -h;
        finite = std::isfinite(value(th, wh));
        for (std::size_t t = 0; t < m && finite; ++t) jac(static_cast<Eigen::Index>(t), static_cast<Eigen::Index>(c)) = (wh[t] - w[t]) / h * unit(j);
      }
      if (!finite) break;
      double cut = INFINITY;  // the Huber loss's corner (robust), none (plain)
      if (robust) {
        std::vector<double> ar(m), aj(m);
        for (std::size_t t = 0; t < m; ++t) {
          ar[t] = std::abs(r(static_cast<Eigen::Index>(t)));
          aj[t] = jac.row(static_cast<Eigen::Index>(t)).norm();
        }
        cut = std::max(2.5 * 1.4826 * median(ar), 1e-300);
        const double jcut = 10.0 * median(aj);
        for (std::size_t t = 0; t < m; ++t) {
          double wt = ar[t] > cut ? cut / ar[t] : 1.0;
          if (aj[t] > jcut && jcut > 0.0) wt *= jcut / aj[t];
          weight(static_cast<Eigen::Index>(t)) = wt;
        }
      }
      auto loss = [&](const std::vector<double>& wv) {
        double l = 0.0;
        for (std::size_t t = 0; t < m; ++t) {
          const double e = std::abs(target_[t] - wv[t]);
          l += e <= cut ? e * e : 2.0 * cut * e - cut * cut;
        }
        return std::isfinite(l) ? l : INFINITY;
      };
      const double now = loss(w);
      const Eigen::MatrixXd a = jac.transpose() * weight.asDiagonal() * jac;
      const Eigen::VectorXd g = jac.transpose() * weight.asDiagonal() * r;
      const double floor = 1e-9 * std::max(1e-300, a.diagonal().maxCoeff());
      bool accepted = false;
      double next = now;
      for (int tries = 0; tries < 5 && !accepted; ++tries) {
        Eigen::MatrixXd damped = a;
        for (Eigen::Index c = 0; c < damped.rows(); ++c) damped(c, c) += mu * (a(c, c) + floor) + floor;
        const Eigen::VectorXd step = damped.ldlt().solve(g);
        std::vector<double> th = theta;
        for (std::size_t c = 0; c < p; ++c) th[free_[c]] += step(static_cast<Eigen::Index>(c)) * unit(free_[c]);
        inside(th);
        if (th == theta) break;
        if (!std::isfinite(value(th, wh))) {
          mu *= 8.0;
          continue;
        }
        const double l = loss(wh);
        if (l < now) {
          accepted = true;
          next = l;
          // The differences over the model's fine structure shorten the steps: while a step twice
          // as long lowers the loss, take it (at most 16 times the first).
          for (double k = 2.0; k <= 16.0; k *= 2.0) {
            std::vector<double> far = theta;
            for (std::size_t c = 0; c < p; ++c) far[free_[c]] += k * step(static_cast<Eigen::Index>(c)) * unit(free_[c]);
            inside(far);
            std::vector<double> wf;
            if (far == th || !std::isfinite(value(far, wf))) break;
            const double lf = loss(wf);
            if (!(lf < next)) break;
            next = lf, th = std::move(far), wh = std::move(wf);
          }
          theta = std::move(th);
          std::swap(w, wh);
          mu = std::max(mu / 4.0, 1e-9);
        } else {
          mu *= 8.0;
        }
      }
      if (!accepted) {
        // The differences read a slope over more than the bowl near theta: again with a third of
        // the increment, down to 1e-5 of the ranges. (Smaller increments from the start read the
        // model's fine structure, steps of int(qN/4) among it, and the fit creeps.)
        if (diff <= 1e-5) break;
        diff = std::max(1e-5, diff / 3.0);
        continue;
      }
      if (now - next < 1e-6 * next) break;
    }
    return {theta, w};
  }

  // A (1+1) evolution strategy at the end, for what the Jacobians do not see: the moments step
  // with int(qN/4), so the distance near a member of the same physics falls to a cusp (each row
  // that crosses a step on one side only adds) whose ridges stop a Jacobian and a search along the
  // axes. Gaussian steps in the scaled coordinates, kept where they lower the distance; the step
  // size grown by 1.5 on a success and shrunk by 1.5^(1/4) on a failure (a success rate of 1/5
  // holds it), from 2 % of each range; it stops after 24 failures in a row (the step down 12-fold).
  void polish(std::vector<double> theta, double f, std::uint64_t stream = 0) {
    Rng rng(derive_seed(derive_seed(o_.seed, f_.name), stream));
    std::vector<double> wh;
    double sigma = 0.02;
    for (int e = 0, failures = 0; e < o_.polish && failures < 24 && f > 0.0; ++e) {
      std::vector<double> th = theta;
      for (std::size_t j : free_) th[j] += sigma * unit(j) * rng.normal();
      inside(th);
      const double fn = value(th, wh);
      if (fn < f) {
        f = fn, theta = std::move(th);
        sigma *= 1.5;
        failures = 0;
      } else {
        sigma *= 0.9036020036098448;  // 1.5^(-1/4)
        ++failures;
      }
    }
  }

  const Whitening& w_;
  const std::vector<double>& target_;
  const SignalFamily& f_;
  std::size_t rows_;
  const IdentityOptions& o_;
  std::vector<std::size_t> free_;
  std::vector<double> y_, z_;
  int evaluations_ = 0;
  double best_f_ = INFINITY;
  std::vector<double> best_theta_;
};

}  // namespace

IdentityBound identity_bound(const std::vector<double>& signal_y, const std::vector<double>& signal_z,
                             const std::vector<double>& noise_y, const std::vector<double>& noise_z, double full_detection_d,
                             const std::vector<SignalFamily>& rivals, const IdentityOptions& options) {
  check_signal_and_noise("identity_bound", signal_y, signal_z, noise_y, noise_z);
  const std::size_t n = signal_y.size();
  IdentityBound bound;
  const Whitening whitening(noise_y, noise_z);
  if (!whitening.ok()) return bound;  // a channel without noise: no bound
  std::vector<double> target;
  whitening.apply(signal_y, signal_z, target);
  const double d2 = squared(target);
  bound.detection_thinned_d = std::sqrt(d2);
  bound.scale = std::isnan(full_detection_d) ? 1.0 : bound.detection_thinned_d > 0.0 ? full_detection_d / bound.detection_thinned_d : 1.0;
  double nearest = INFINITY;
  for (const SignalFamily& f : rivals) {
    Fit fit(whitening, target, f, n, options);
    auto [f2, theta] = fit.run();
    RivalDistance r;
    r.name = f.name;
    // Every family holds the no-effect member: no farther than |s_E|.
    r.d = std::sqrt(std::min(f2, d2)) * bound.scale;
    r.theta = std::move(theta);
    r.evaluations = fit.evaluations();
    if (r.d < nearest) nearest = r.d, bound.rival = r.name;
    bound.rivals.push_back(std::move(r));
  }
  if (!rivals.empty()) {
    bound.d = nearest;
    bound.power = power_at_one_percent(nearest);
  }
  return bound;
}

std::vector<std::size_t> thinned_rows(std::size_t n, std::size_t max_rows) {
  const std::size_t k = std::max<std::size_t>(1, (n + std::max<std::size_t>(1, max_rows) - 1) / std::max<std::size_t>(1, max_rows));
  std::vector<std::size_t> rows;
  rows.reserve(n / k + 1);
  for (std::size_t i = 0; i < n; i += k) rows.push_back(i);
  return rows;
}

std::vector<std::string> identity_rivals(const std::string& name) {
  const std::regex own(hidden_effect_pattern(name));
  std::vector<std::string> out;
  for (const HiddenEffectInfo& e : hidden_effect_table()) {
    if (e.name == name || std::regex_search(e.name, own)) continue;       // a name that counts
    if (std::regex_search(name, std::regex(e.pattern))) continue;          // the same effect under a zoo label
    out.push_back(e.name);
  }
  return out;
}

SignalFamily signal_family(const std::string& name, const CouplingModel& model, double jam_rad, const Channels& clean,
                           std::vector<std::size_t> rows) {
  auto family = std::make_shared<HiddenEffectFamily>(hidden_effect_family(name, model, jam_rad, clean, true));
  SignalFamily s;
  s.name = name;
  s.parameters = family->parameters;
  s.none = family->none;
  // The family's theta from the fit's: a size and its direction as the vector's components.
  const int size = family->size_parameter, angle = family->polar_angle;
  const bool polar = size >= 0 && angle >= 0;
  std::function<std::vector<double>(const std::vector<double>&)> theta_of = [](const std::vector<double>& v) { return v; };
  if (polar) {
    const EffectParameter length = family->parameters[static_cast<std::size_t>(size)];
    const double most = std::max(std::abs(length.lo), std::abs(length.hi));
    const double scale = std::isfinite(most) ? most : length.scale;
    s.parameters[static_cast<std::size_t>(size)] = {length.name + " cos", -most, most, scale};
    s.parameters[static_cast<std::size_t>(angle)] = {length.name + " sin", -most, most, scale};
    s.none[static_cast<std::size_t>(size)] = s.none[static_cast<std::size_t>(angle)] = 0.0;
    s.size_parameters = {size, angle};
    theta_of = [size, angle](const std::vector<double>& v) {
      std::vector<double> theta = v;
      const double x = v[static_cast<std::size_t>(size)], y = v[static_cast<std::size_t>(angle)];
      theta[static_cast<std::size_t>(size)] = std::hypot(x, y);
      theta[static_cast<std::size_t>(angle)] = std::atan2(y, x);
      return theta;
    };
    // The length within the size's range and the family's own constraints, then back.
    s.project = [family, size, angle, length, theta_of](std::vector<double>& v) {
      std::vector<double> theta = theta_of(v);
      double& r = theta[static_cast<std::size_t>(size)];
      r = std::clamp(r, length.lo, length.hi);
      if (family->project) family->project(theta);
      const double a = theta[static_cast<std::size_t>(angle)];
      v = theta;
      v[static_cast<std::size_t>(size)] = theta[static_cast<std::size_t>(size)] * std::cos(a);
      v[static_cast<std::size_t>(angle)] = theta[static_cast<std::size_t>(size)] * std::sin(a);
    };
  } else {
    if (size >= 0) s.size_parameters = {size};
    s.project = family->project;
  }
  s.signal = [family, theta_of, &clean, rows = std::move(rows)](const std::vector<double>& v, std::vector<double>& y, std::vector<double>& z) {
    const std::vector<double> theta = theta_of(v);
    y.assign(rows.size(), 0.0);
    z.assign(rows.size(), 0.0);
    for (std::size_t k = 0; k < rows.size(); ++k) {
      const std::size_t i = rows[k];
      try {
        const SensorMoments m = family->moments(theta, i);
        const double dy = m.y_nm - clean.msy_nm[i], dz = m.z_nm - clean.msz_nm[i];
        if (std::isfinite(dy) && std::isfinite(dz)) y[k] = dy, z[k] = dz;
      } catch (const std::exception&) {
        // the model refuses the row: no change, as the generator leaves it
      }
    }
  };
  return s;
}

}  // namespace gc::zoo
