#include "tests/diagnosis/zoo/hidden_effects.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <unordered_map>

#include "core/restoring_torque.h"
#include "tests/diagnosis/independent/truth_physics.h"
#include "tests/diagnosis/zoo/text.h"

namespace gc::zoo {
namespace {

constexpr double kPi = std::numbers::pi;

// One truth in physical form: the sensor moments at row i with the effect's amplitude parameters
// times lambda (shape parameters fixed), lambda at most lam_max (the physical bounds).
struct Physical {
  std::function<SensorMoments(double lam, std::size_t i)> moments;
  std::function<std::string(double lam)> describe;
  double lam_max = std::numeric_limits<double>::infinity();
  // The RMS may jump with lambda (int(qN/4) steps: on a torque staircase every row of a level
  // crosses a step at once), so the proportional steps can cycle around the target: bracket it
  // and bisect, and keep the lambda whose RMS is nearest (a target inside a jump is out of reach;
  // the touch-up, printed, carries the rest). Off for the truths that predate it (their draws stay).
  bool bracket = false;
};

// Solves lambda on a subsample so the physics gives the target RMS, evaluates every row, and
// touches the change up linearly to the exact target.
std::string apply_physical(const Physical& p, double target, Channels& truth) {
  const std::size_t n = truth.rows();
  const std::size_t stride = std::max<std::size_t>(1, n / 2500);
  std::vector<double> dy(n, 0.0), dz(n, 0.0);
  std::size_t fails = 0;
  auto rms = [&](double lam, std::size_t step, bool keep) {
    double ss = 0.0;
    std::size_t m = 0;
    for (std::size_t i = 0; i < n; i += step, ++m) {
      double y = 0.0, z = 0.0;
      try {
        const SensorMoments s = p.moments(lam, i);
        y = s.y_nm - truth.msy_nm[i];
        z = s.z_nm - truth.msz_nm[i];
        if (!std::isfinite(y) || !std::isfinite(z)) throw std::runtime_error("not finite");
      } catch (const std::exception&) {
        y = z = 0.0;
        if (keep) ++fails;
      }
      if (keep) dy[i] = y, dz[i] = z;
      ss += y * y + z * z;
    }
    return m ? std::sqrt(ss / (2.0 * static_cast<double>(m))) : 0.0;
  };
  double lam = std::min(1.0, p.lam_max);
  // Bracketing (p.bracket): the largest lambda seen below the target, the smallest above it, and
  // the lambda nearest to it (in the ratio).
  double below = 0.0, above = std::numeric_limits<double>::infinity(), best = lam;
  double best_miss = std::numeric_limits<double>::infinity();
  bool reached = false;
  auto seen = [&](double l, double r) {
    if (!(r > 0.0)) return;
    if (r < target) below = std::max(below, l);
    else above = std::min(above, l);
    const double miss = std::abs(std::log(r / target));
    if (miss < best_miss) best_miss = miss, best = l;
  };
  for (int it = 0; it < 8; ++it) {
    const double r = rms(lam, stride, false);
    seen(lam, r);
    if (!(r > 0.0) || std::abs(r / target - 1.0) < 0.02) {
      reached = true;
      break;
    }
    const double next = std::min(p.lam_max, lam * target / r);
    if (next == lam) break;
    lam = next;
  }
  if (p.bracket && !reached) {
    for (int it = 0; it < 40 && below > 0.0 && std::isfinite(above) && above - below > 1e-9 * above; ++it) {
      const double mid = 0.5 * (below + above), r = rms(mid, stride, false);
      seen(mid, r);
      if (r > 0.0 && std::abs(r / target - 1.0) < 0.02) break;
      if (!(r > 0.0) || r < target) below = mid;
      else above = mid;
    }
    if (std::isfinite(best_miss)) lam = best;
  }
  const double r = rms(lam, 1, true);
  const double k = r > 0.0 ? target / r : 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    truth.msy_nm[i] += k * dy[i];
    truth.msz_nm[i] += k * dz[i];
  }
  std::string out = p.describe(lam) + format("; lambda %.3g, touch-up x%.3f", lam, k);
  if (fails) out += format(", %zu rows unsolved (left unchanged)", fails);
  if (!(r > 0.0)) out += ", INVISIBLE in this programme (nothing added)";
  return out;
}

double signed_uniform(Rng& rng, double lo, double hi) { return (rng.chance(0.5) ? 1.0 : -1.0) * rng.uniform(lo, hi); }

constexpr double kInf = std::numeric_limits<double>::infinity();

EffectParameter held(const char* name, double v) { return {name, v, v, v != 0.0 ? std::abs(v) : 1.0}; }
EffectParameter ranged(const char* name, double lo, double hi) { return {name, lo, hi, hi - lo}; }
EffectParameter angle(const char* name) { return {name, -kInf, kInf, kPi}; }

// Rebuilt models (coupling or contact options changed), cached by the value they were built at.
class Rebuilt {
 public:
  using Change = std::function<void(double key, CouplingDefinition&, ContactOptions&)>;
  Rebuilt(const CouplingModel& base, Change change) : base_(base), change_(std::move(change)) {}
  const CouplingModel& at(double key) {
    auto it = cache_.find(key);
    if (it != cache_.end()) return *it->second;
    CouplingDefinition c = base_.base_coupling();
    ContactOptions o = base_.options();
    change_(key, c, o);
    return *(cache_[key] = std::make_shared<CouplingModel>(c, base_.effects(), o));
  }

 private:
  const CouplingModel& base_;
  Change change_;
  std::map<double, std::shared_ptr<CouplingModel>> cache_;
};

// A contact change (independent::with_contact_change) at row i of `clean`; with remember_rows the
// base prediction and its contact moments are kept per row (the same arithmetic, to the bit).
class ContactChanges {
 public:
  ContactChanges(const CouplingModel& model, const Channels& clean, bool remember) : model_(model), clean_(clean), remember_(remember) {}
  SensorMoments at(std::size_t i, const independent::ContactChange& change) {
    if (!remember_) return independent::with_contact_change(model_, clean_.sample(i), change);
    auto it = base_.find(i);
    if (it == base_.end()) {
      const ModelPrediction p = model_.predict(clean_.sample(i));
      const Eigen::Vector2d before = independent::contact_moments(model_.geometry(), p.state.point, p.state.contact, p.state.frame_shift_rad);
      it = base_.emplace(i, Base{p, before}).first;
    }
    const ModelPrediction& p = it->second.p;
    OperatingPoint point = p.state.point;
    double shift_rad = p.state.frame_shift_rad;
    change(point, shift_rad);
    const Eigen::Vector2d after = independent::contact_moments(model_.geometry(), point, p.state.contact, shift_rad);
    return {p.moments.y_nm + after.x() - it->second.before.x(), p.moments.z_nm + after.y() - it->second.before.y()};
  }

 private:
  struct Base {
    ModelPrediction p;
    Eigen::Vector2d before;
  };
  const CouplingModel& model_;
  const Channels& clean_;
  bool remember_;
  std::unordered_map<std::size_t, Base> base_;
};

double largest_spread(const Channels& c) {
  double s = 0.0;
  for (const auto* v : {&c.msy_nm, &c.msz_nm}) {
    if (v->empty()) continue;
    const auto [lo, hi] = std::minmax_element(v->begin(), v->end());
    s = std::max(s, *hi - *lo);
  }
  return s > 0.0 ? s : 1.0;
}

}  // namespace

HiddenEffectFamily hidden_effect_family(const std::string& name, const CouplingModel& model, double jam,
                                        const Channels& truth, bool remember_rows) {
  const double tm = restoring_torque(model.geometry()).torque_nm;
  const double tscale = tm / 1.36e6;  // torques of the doc's ranges, for this coupling's size
  const double phi = model.geometry().pressure_angle_rad();
  const double spread = largest_spread(truth);  // sizes of the additive signals: a share of it
  HiddenEffectFamily f;
  f.name = name;
  using Theta = std::vector<double>;
  if (name == "torque_gain") {
    // Section 3: the torque transducer's gain: the coupling carries T (1 + g) when T is logged.
    // The moments are the model's at the carried torque, solved at every size: the number of
    // teeth summed, int(qN/4), steps with the torque, so a trial change scaled is no gain at all.
    f.parameters = {ranged("g", -0.5, 0.5), held("lambda", 1.0)};
    f.none = {0.0, 1.0};
    f.size_parameter = 0;
    f.moments = [&model, &truth](const Theta& th, std::size_t i) {
      const double g = th[0], lam = th[1];
      MeasurementSample s = truth.sample(i);
      s.torque_nm *= 1.0 + lam * g;
      return model.predict(s).moments;
    };
  } else if (name == "misalignment_offset" || name == "assembly_misalignment") {
    // Section 6.3.1: an unseen constant misalignment vector at a random direction, summed with the
    // recorded vector; the moments are the model's at the sum (int(qN/4) steps with the
    // misalignment too: solved at every size, never scaled). The offset at most 0.3 xi; the
    // assembly misalignment at most 0.05 rad and 0.35 xi. A size of either sign: the direction's
    // opposite.
    const double most = name == "misalignment_offset" ? 0.3 * jam : std::min(0.05, 0.35 * jam);
    f.parameters = {ranged("zeta0", -most, most), angle("beta0"), held("lambda", 1.0)};
    f.none = {0.0, 0.0, 1.0};
    f.size_parameter = 0;
    f.polar_angle = 1;
    f.moments = [&model, &truth](const Theta& th, std::size_t i) {
      const double z0 = th[0], b0 = th[1], lam = th[2];
      return model.predict(independent::with_added_misalignment(truth.sample(i), lam * z0, b0)).moments;
    };
  } else if (name == "friction") {
    // Section 6.3: mu rises at low torque and with misalignment: mu0 + a T_ref / T + b zeta / xi.
    // The ranges: the drawn ones (mu0 0.02-0.3, a 0-0.15, b 0-0.3) at lambda <= 3.
    const double tref = 1.5e6 * tscale;
    auto contact = std::make_shared<ContactChanges>(model, truth, remember_rows);
    f.parameters = {ranged("mu0", 0.1 + 3.0 * (0.02 - 0.1), 0.1 + 3.0 * (0.3 - 0.1)), ranged("a", 0.0, 0.45), ranged("b", 0.0, 0.9),
                    held("lambda", 1.0)};
    f.none = {0.1, 0.0, 0.0, 1.0};
    f.moments = [contact, tref, jam](const Theta& th, std::size_t i) {
      const double mu0 = th[0], a = th[1], b = th[2], lam = th[3];
      return contact->at(i, [=](OperatingPoint& op, double&) {
        const double drawn = mu0 + a * tref / op.torque_nm + b * op.misalignment_rad / jam;
        op.friction_coefficient = std::clamp(0.1 + lam * (drawn - 0.1), 0.0, 0.6);
      });
    };
  } else if (name == "self_weight") {
    // Eq 48 by its own statics: the hub and half the shaft, s times the coupling file's weights
    // (s 0.5-0.9 at lambda <= 1 / (1 - s), 1.1-2 at lambda <= 4 / (s - 1): (s - 1) lambda in -1..4).
    const double w = independent::weight_moment_nm(model.base_coupling());
    f.parameters = {ranged("s", 0.0, 5.0), held("lambda", 1.0)};
    f.none = {1.0, 1.0};
    f.moments = [&truth, w](const Theta& th, std::size_t i) {
      const double s = th[0], lam = th[1];
      return SensorMoments{truth.msy_nm[i] - lam * (s - 1.0) * w, truth.msz_nm[i]};
    };
  } else if (name == "pressure_angle_rotation") {
    // Eqs 44-47: the moments turn by s phi T / (T + T_s) instead of the paper's phi; lambda at most
    // 1 / |1 - s| (20 at most).
    auto contact = std::make_shared<ContactChanges>(model, truth, remember_rows);
    f.parameters = {ranged("s", 0.0, 1.5), ranged("T_s", 0.0, 1.5e6 * tscale), ranged("lambda", 0.0, 20.0)};
    f.none = {1.0, 0.0, 0.0};
    f.size_parameter = 2;
    f.moments = [contact, phi](const Theta& th, std::size_t i) {
      const double s = th[0], ts = th[1], lam = th[2];
      return contact->at(i, [=](OperatingPoint& op, double& shift) {
        shift += lam * (s * phi * op.torque_nm / (op.torque_nm + ts) - phi);
      });
    };
    f.project = [](Theta& th) {
      const double s = th[0];
      const double most = s < 1.0 ? 1.0 / (1.0 - s) : s > 1.0 ? 1.0 / (s - 1.0) : 20.0;
      th[2] = std::clamp(th[2], 0.0, std::min(20.0, most));
    };
  } else if (name == "eccentricity") {
    // Eqs 49-53: the hub sags on the sleeve below the centring torque s T_m, along gravity (its
    // size at most 0.01 rad and 0.35 xi; either sign, the opposite direction).
    const double most = std::min(0.01, 0.35 * jam);
    f.parameters = {ranged("zeta_e", -most, most), ranged("s", 0.5, 2.0), ranged("k", 1.0, 10.0), angle("gravity"), held("lambda", 1.0)};
    f.none = {0.0, 1.0, 1.0, 0.0, 1.0};
    f.size_parameter = 0;
    f.polar_angle = 3;
    f.moments = [&model, &truth, tm](const Theta& th, std::size_t i) {
      const double ze = th[0], s = th[1], k = th[2], g = th[3], lam = th[4];
      const double t = truth.torque_nm[i], thr = s * tm;
      const double fade = t < thr ? 1.0 - std::pow(t / thr, k) : 0.0;
      return model.predict(independent::with_added_misalignment(truth.sample(i), lam * ze * fade, g)).moments;
    };
  } else if (name == "compliance") {
    // Section 6.1: rim and shaft flexibility in series with the mesh, C_rim = r C: the mesh at
    // r / (1 + r) of eq 5's stiffness (through E); lambda scales the rim's compliance 1/r, at most
    // 9 r (the mesh at 0.1 of eq 5 or more).
    auto rebuilt = std::make_shared<Rebuilt>(model, [](double factor, CouplingDefinition& c, ContactOptions&) { c.youngs_modulus_pa *= factor; });
    f.parameters = {held("r", 1.0), ranged("lambda", 0.0, 9.0)};
    f.none = {1.0, 0.0};
    f.size_parameter = 1;
    f.moments = [rebuilt, &truth](const Theta& th, std::size_t i) {
      const double r = th[0], lam = th[1];
      return rebuilt->at(1.0 / (1.0 + lam / r)).predict(truth.sample(i)).moments;
    };
  } else if (name == "spacing_errors") {
    // Sections 1, 6.4: an out-of-round sleeve separates the teeth by e more (eq 11's z_o), at
    // most 100 um.
    auto rebuilt = std::make_shared<Rebuilt>(model, [](double e, CouplingDefinition&, ContactOptions& o) { o.spacing_error_m += e; });
    f.parameters = {held("e", 1e-6), ranged("lambda", 0.0, 100.0)};
    f.none = {1e-6, 0.0};
    f.size_parameter = 1;
    f.moments = [rebuilt, &truth](const Theta& th, std::size_t i) {
      const double e = th[0], lam = th[1];
      return rebuilt->at(lam * e).predict(truth.sample(i)).moments;
    };
  } else if (name == "channel_gain_offset") {
    // Section 3: the bending bridges' residual calibration: (1 + g) M + o on each channel, |g| at
    // most 0.5, |o| at most 2 MN·m (the generator's bounds on lambda).
    f.parameters = {ranged("g_y", -0.5, 0.5), ranged("g_z", -0.5, 0.5), ranged("o_y", -2e6, 2e6), ranged("o_z", -2e6, 2e6), held("lambda", 1.0)};
    f.none = {0.0, 0.0, 0.0, 0.0, 1.0};
    f.moments = [&truth](const Theta& th, std::size_t i) {
      const double gy = th[0], gz = th[1], oy = th[2], oz = th[3], lam = th[4];
      return SensorMoments{(1 + lam * gy) * truth.msy_nm[i] + lam * oy, (1 + lam * gz) * truth.msz_nm[i] + lam * oz};
    };
  } else if (name == "hysteresis") {
    // Section 6.3: the coupling lags the measured misalignment by `lag` against the direction of
    // travel of the true misalignment (sticky: a hold keeps the last travel); lag at most 0.01 rad
    // and 0.2 xi.
    auto travel = std::make_shared<std::vector<int>>(truth.rows(), 0);
    for (std::size_t i = 1; i < truth.rows(); ++i) {
      const double d = truth.zeta_rad[i] - truth.zeta_rad[i - 1];
      (*travel)[i] = std::abs(d) > 1e-9 * jam ? (d > 0 ? 1 : -1) : (*travel)[i - 1];
    }
    f.parameters = {ranged("lag", 0.0, std::min(0.01, 0.2 * jam)), held("lambda", 1.0)};
    f.none = {0.0, 1.0};
    f.size_parameter = 0;
    f.moments = [&model, &truth, travel](const Theta& th, std::size_t i) {
      const double lag = th[0], lam = th[1];
      MeasurementSample s = truth.sample(i);
      s.misalignment_rad = std::max(0.0, s.misalignment_rad - (*travel)[i] * lam * lag);
      return model.predict(s).moments;
    };
  } else if (name == "misalignment_scale") {
    // Section 3: the displacement sensors' lever arm: the coupling sees (1 + k) zeta, |k| <= 0.5.
    f.parameters = {ranged("k", -0.5, 0.5), held("lambda", 1.0)};
    f.none = {0.0, 1.0};
    f.size_parameter = 0;
    f.moments = [&model, &truth](const Theta& th, std::size_t i) {
      const double k = th[0], lam = th[1];
      MeasurementSample s = truth.sample(i);
      s.misalignment_rad *= 1.0 + lam * k;
      return model.predict(s).moments;
    };
  } else if (name == "torque_calibration") {
    // Section 3: the torque flange's slope and curvature: T carried = T (1 + k + c T / 1 MN·m),
    // |k|, |c| <= 0.5.
    f.parameters = {ranged("k", -0.5, 0.5), ranged("c", -0.5, 0.5), held("lambda", 1.0)};
    f.none = {0.0, 0.0, 1.0};
    f.moments = [&model, &truth](const Theta& th, std::size_t i) {
      const double k = th[0], c = th[1], lam = th[2];
      MeasurementSample s = truth.sample(i);
      s.torque_nm *= 1.0 + lam * (k + c * s.torque_nm / 1e6);
      return model.predict(s).moments;
    };
  } else if (name == "thermal_misalignment") {
    // The housing grows with the oil temperature: g (theta - theta_0) added along beta_t; |g| at
    // most 2e-3 rad/degC and 0.35 xi over the record's temperatures.
    double tlo = kInf, thi = -kInf;
    for (double t : truth.temperature_c) tlo = std::min(tlo, t), thi = std::max(thi, t);
    f.parameters = {ranged("g", -2e-3, 2e-3), ranged("theta_0", 15.0, 40.0), angle("beta_t"), held("lambda", 1.0)};
    f.none = {0.0, 25.0, 0.0, 1.0};
    f.size_parameter = 0;
    f.polar_angle = 2;
    f.moments = [&model, &truth](const Theta& th, std::size_t i) {
      const double g = th[0], th0 = th[1], bt = th[2], lam = th[3];
      return model.predict(independent::with_added_misalignment(truth.sample(i), lam * g * (truth.temperature_c[i] - th0), bt)).moments;
    };
    f.project = [tlo, thi, jam](Theta& th) {
      const double dmax = std::max(std::abs(thi - th[1]), std::abs(tlo - th[1]));
      const double most = std::min(2e-3, dmax > 0 ? 0.35 * jam / dmax : kInf);
      th[0] = std::clamp(th[0], -most, most);
    };
  } else if (name == "moment_delay") {
    // Section 3: the bridges reach the DAQ through another path: M(t - tau) (a skew), and a
    // demodulator's mean over the last N revolutions (the moments averaged, 60 N / n s); tau
    // -2..5 s, N at most 10.
    const std::size_t n = truth.rows();
    auto cy = std::make_shared<std::vector<double>>(n, 0.0), cz = std::make_shared<std::vector<double>>(n, 0.0);
    for (std::size_t i = 1; i < n; ++i) {
      const double dt = truth.time_s[i] - truth.time_s[i - 1];
      (*cy)[i] = (*cy)[i - 1] + 0.5 * dt * (truth.msy_nm[i] + truth.msy_nm[i - 1]);
      (*cz)[i] = (*cz)[i - 1] + 0.5 * dt * (truth.msz_nm[i] + truth.msz_nm[i - 1]);
    }
    // Value and running integral of the moments (linear between samples, held beyond the ends).
    auto at = [&truth, cy, cz, n](double t, bool integral) -> std::pair<double, double> {
      const auto& ts = truth.time_s;
      if (t <= ts[0]) {
        return integral ? std::pair{(t - ts[0]) * truth.msy_nm[0], (t - ts[0]) * truth.msz_nm[0]} : std::pair{truth.msy_nm[0], truth.msz_nm[0]};
      }
      if (t >= ts[n - 1]) {
        const double d = t - ts[n - 1];
        return integral ? std::pair{(*cy)[n - 1] + d * truth.msy_nm[n - 1], (*cz)[n - 1] + d * truth.msz_nm[n - 1]}
                        : std::pair{truth.msy_nm[n - 1], truth.msz_nm[n - 1]};
      }
      const std::size_t j = static_cast<std::size_t>(std::upper_bound(ts.begin(), ts.end(), t) - ts.begin()) - 1;
      const double h = ts[j + 1] - ts[j], fr = h > 0 ? (t - ts[j]) / h : 0.0;
      const double y = truth.msy_nm[j] + fr * (truth.msy_nm[j + 1] - truth.msy_nm[j]);
      const double z = truth.msz_nm[j] + fr * (truth.msz_nm[j + 1] - truth.msz_nm[j]);
      if (!integral) return {y, z};
      const double d = t - ts[j];
      return {(*cy)[j] + 0.5 * d * (truth.msy_nm[j] + y), (*cz)[j] + 0.5 * d * (truth.msz_nm[j] + z)};
    };
    f.parameters = {ranged("tau", -2.0, 5.0), ranged("revolutions", 0.0, 10.0), held("lambda", 1.0)};
    f.none = {0.0, 0.0, 1.0};
    f.moments = [&truth, at](const Theta& th, std::size_t i) {
      const double tau = th[0], revs = th[1], lam = th[2];
      const double b = truth.time_s[i] - lam * tau;
      const double w = lam * revs * 60.0 / std::max(0.1, truth.speed_rpm[i]);
      if (w <= 1e-9) {
        const auto [y, z] = at(b, false);
        return SensorMoments{y, z};
      }
      const auto [yb, zb] = at(b, true);
      const auto [ya, za] = at(b - w, true);
      return SensorMoments{(yb - ya) / w, (zb - za) / w};
    };
  } else if (name == "continuous_quarter_sums") {
    // Eqs 13, 42-43: a real coupling has no int(qN/4) sawtooth; the truth is the continuous form
    // (a switch: its change is scaled, lambda >= 0).
    auto rebuilt = std::make_shared<Rebuilt>(model, [](double, CouplingDefinition&, ContactOptions& o) { o.continuous_quarter_sums = true; });
    auto kept = std::make_shared<std::unordered_map<std::size_t, SensorMoments>>();
    f.parameters = {{"lambda", 0.0, kInf, 1.0}};
    f.none = {0.0};
    f.size_parameter = 0;
    f.moments = [rebuilt, kept, remember_rows, &truth](const Theta& th, std::size_t i) {
      const double lam = th[0];
      SensorMoments m;
      if (!remember_rows) {
        m = rebuilt->at(1.0).predict(truth.sample(i)).moments;
      } else {
        auto it = kept->find(i);
        if (it == kept->end()) it = kept->emplace(i, rebuilt->at(1.0).predict(truth.sample(i)).moments).first;
        m = it->second;
      }
      return SensorMoments{truth.msy_nm[i] + lam * (m.y_nm - truth.msy_nm[i]), truth.msz_nm[i] + lam * (m.z_nm - truth.msz_nm[i])};
    };
  } else if (name == "speed_drag") {
    // A formula's physics (`expression`): a seal's viscous drag, proportional to the shaft
    // speed, read by the bending bridges through their cross-sensitivity, at a fixed angle.
    double mean_rpm = 0.0;
    for (double v : truth.speed_rpm) mean_rpm += std::abs(v);
    mean_rpm = truth.rows() ? std::max(1.0, mean_rpm / static_cast<double>(truth.rows())) : 1.0;
    f.parameters = {angle("a"), {"lambda", -kInf, kInf, 0.05 * spread / (1000.0 * mean_rpm)}};
    f.none = {0.0, 0.0};
    f.size_parameter = 1;
    f.polar_angle = 0;
    f.moments = [&truth](const Theta& th, std::size_t i) {
      const double a = th[0], lam = th[1];
      const double m = lam * 1000.0 * truth.speed_rpm[i];
      return SensorMoments{truth.msy_nm[i] + m * std::cos(a), truth.msz_nm[i] + m * std::sin(a)};
    };
  } else if (name == "twice_per_rev") {
    // An oval sleeve: A (cos, sin)(2 phi + p), phi the shaft angle (an additive signal).
    auto angle_rad = std::make_shared<std::vector<double>>(truth.rows(), 0.0);
    double a = 0.0;
    for (std::size_t i = 1; i < truth.rows(); ++i) {
      a += 0.5 * (truth.speed_rpm[i] + truth.speed_rpm[i - 1]) * 2 * std::numbers::pi / 60.0 * (truth.time_s[i] - truth.time_s[i - 1]);
      (*angle_rad)[i] = a;
    }
    f.parameters = {angle("p"), {"A", -kInf, kInf, 0.05 * spread}};
    f.none = {0.0, 0.0};
    f.size_parameter = 1;
    f.polar_angle = 0;
    f.moments = [&truth, angle_rad](const Theta& th, std::size_t i) {
      const double p = th[0], amp = th[1], ph = (*angle_rad)[i];
      return SensorMoments{truth.msy_nm[i] + amp * std::cos(2 * ph + p), truth.msz_nm[i] + amp * std::sin(2 * ph + p)};
    };
  } else if (name == "weight") {
    // A heavier (or lighter) hub: M_sy' lower by a constant (an additive signal).
    f.parameters = {{"w", -kInf, kInf, 0.05 * spread}};
    f.none = {0.0};
    f.size_parameter = 0;
    f.moments = [&truth](const Theta& th, std::size_t i) { return SensorMoments{truth.msy_nm[i] - th[0], truth.msz_nm[i]}; };
  } else {
    throw std::invalid_argument("unknown hidden effect " + name);
  }
  return f;
}

namespace {

// The generator's member of a family: its drawn shape parameters, then lambda.
std::function<SensorMoments(double, std::size_t)> member(const std::string& name, const CouplingModel& model, double jam,
                                                         const Channels& truth, std::vector<double> shape) {
  auto family = std::make_shared<HiddenEffectFamily>(hidden_effect_family(name, model, jam, truth));
  return [family, shape = std::move(shape)](double lam, std::size_t i) {
    std::vector<double> theta = shape;
    theta.push_back(lam);
    return family->moments(theta, i);
  };
}

Physical make_physical(const std::string& name, const CouplingModel& model, double jam, const Channels& truth, Rng& rng) {
  const double tm = restoring_torque(model.geometry()).torque_nm;
  const double tscale = tm / 1.36e6;  // torques of the doc's ranges, for this coupling's size
  const double inf = std::numeric_limits<double>::infinity();
  Physical p;
  std::vector<double> shape;  // the drawn shape parameters (hidden_effect_family's, lambda last)
  if (name == "torque_gain") {
    const double g = signed_uniform(rng, 0.01, 0.05);
    shape = {g};
    p.describe = [=](double lam) { return format("gain %+.2f %% (drawn %+.2f %%)", 100.0 * lam * g, 100.0 * g); };
    p.lam_max = 0.5 / std::abs(g);
    p.bracket = true;
  } else if (name == "misalignment_offset") {
    // 2 % of the jam angle (times lambda) at a random direction.
    const double z0 = 0.02 * jam, b0 = rng.uniform(-kPi, kPi);
    shape = {z0, b0};
    p.describe = [=](double lam) {
      return format("offset %.4f xi (%.3g mrad) at %.2f rad (drawn 0.02 xi)", lam * z0 / jam, lam * z0 * 1e3, b0);
    };
    p.lam_max = 0.3 * jam / z0;
    p.bracket = true;
  } else if (name == "friction") {
    const double mu0 = rng.uniform(0.02, 0.3), a = rng.uniform(0.0, 0.15), b = rng.uniform(0.0, 0.3), tref = 1.5e6 * tscale;
    shape = {mu0, a, b};
    p.describe = [=](double lam) {
      return format("mu = %.4f + %.4f T_ref/T + %.4f zeta/xi (drawn %.3f, %.3f, %.3f), T_ref %.3g MN·m, capped to [0, 0.6]",
                    0.1 + lam * (mu0 - 0.1), lam * a, lam * b, mu0, a, b, tref / 1e6);
    };
    p.lam_max = 3.0;
  } else if (name == "self_weight") {
    const double s = rng.chance(0.5) ? rng.uniform(0.5, 0.9) : rng.uniform(1.1, 2.0);
    const double w = independent::weight_moment_nm(model.base_coupling());
    shape = {s};
    p.describe = [=](double lam) { return format("weight scale %.3f -> %.3f of %.4g kN·m", s, 1.0 + lam * (s - 1.0), w / 1e3); };
    p.lam_max = s > 1 ? 4.0 / (s - 1.0) : 1.0 / (1.0 - s);
  } else if (name == "pressure_angle_rotation") {
    const double s = rng.uniform(0.0, 1.5), ts = rng.chance(0.3) ? 0.0 : rng.uniform(0.0, 1.5e6) * tscale;
    shape = {s, ts};
    p.describe = [=](double lam) {
      return format("shift phi (1 - lambda) + lambda s phi T/(T + T_s), s %.3f, T_s %.3g MN·m (T_s 0: s_eff %.3f)", s, ts / 1e6, 1 + lam * (s - 1));
    };
    p.lam_max = s < 1 ? 1.0 / (1.0 - s) : (s > 1 ? 1.0 / (s - 1.0) : 1.0);
  } else if (name == "assembly_misalignment") {
    const double z0 = rng.uniform(0.05, 0.3) * jam, b0 = rng.uniform(-kPi, kPi);
    shape = {z0, b0};
    p.describe = [=](double lam) { return format("zeta0 %.3f xi at %.2f rad", lam * z0 / jam, b0); };
    p.lam_max = std::min(0.05, 0.35 * jam) / z0;
  } else if (name == "eccentricity") {
    const double ze = rng.uniform(0.05, 0.3) * jam, s = rng.uniform(0.5, 2.0), k = rng.chance(0.5) ? 1.0 : rng.uniform(1.0, 10.0);
    const double g = rng.uniform(-kPi, kPi);
    shape = {ze, s, k, g};
    p.describe = [=](double lam) {
      return format("zeta_e %.3f xi, threshold %.2f T_m (T_m %.3g MN·m), sharpness %.2f, gravity %.2f rad", lam * ze / jam, s, tm / 1e6, k, g);
    };
    p.lam_max = std::min(0.01, 0.35 * jam) / ze;
  } else if (name == "compliance") {
    const double r = rng.uniform(1.5, 20.0);
    shape = {r};
    p.describe = [=](double lam) { return format("rim stiffness %.3g C: mesh at %.3f of eq 5", r, 1.0 / (1.0 + lam / r)); };
    p.lam_max = 9.0 * r;
  } else if (name == "spacing_errors") {
    const double e = rng.uniform(5e-6, 5e-5);
    shape = {e};
    p.describe = [=](double lam) { return format("spacing error %.3g um", lam * e * 1e6); };
    p.lam_max = 1e-4 / e;
  } else if (name == "channel_gain_offset") {
    const double gy = rng.uniform(-0.1, 0.1), gz = rng.uniform(-0.1, 0.1);
    const double oy = (rng.chance(0.5) ? 1 : -1) * rng.log_uniform(1e3, 2e5) * tscale;
    const double oz = (rng.chance(0.5) ? 1 : -1) * rng.log_uniform(1e3, 2e5) * tscale;
    shape = {gy, gz, oy, oz};
    p.describe = [=](double lam) {
      return format("gains %+.4f %+.4f, offsets %+.4g %+.4g kN·m", lam * gy, lam * gz, lam * oy / 1e3, lam * oz / 1e3);
    };
    p.lam_max = std::min(0.5 / std::max(std::abs(gy), std::abs(gz)), 2e6 / std::max(std::abs(oy), std::abs(oz)));
  } else if (name == "hysteresis") {
    const double lag = rng.uniform(0.02, 0.1) * jam;
    shape = {lag};
    p.describe = [=](double lam) { return format("lag %.4f xi (%.3g mrad)", lam * lag / jam, lam * lag * 1e3); };
    p.lam_max = std::min(0.01, 0.2 * jam) / lag;
  } else if (name == "misalignment_scale") {
    const double k = signed_uniform(rng, 0.03, 0.2);
    shape = {k};
    p.describe = [=](double lam) { return format("zeta seen = (1 %+.4f) zeta measured", lam * k); };
    p.lam_max = 0.5 / std::abs(k);
  } else if (name == "torque_calibration") {
    const double k = rng.uniform(-0.05, 0.05), c = rng.uniform(-0.05, 0.05);
    shape = {k, c};
    p.describe = [=](double lam) { return format("slope %+.4f, curvature %+.4f per MN·m", lam * k, lam * c); };
    p.lam_max = 0.5 / std::max(std::abs(k), std::abs(c));
  } else if (name == "thermal_misalignment") {
    const double g = signed_uniform(rng, 2e-5, 2e-4), th0 = rng.uniform(15.0, 40.0), bt = rng.uniform(-kPi, kPi);
    double dmax = 0.0;
    for (double t : truth.temperature_c) dmax = std::max(dmax, std::abs(t - th0));
    shape = {g, th0, bt};
    p.describe = [=](double lam) { return format("growth %.3g rad/degC from %.1f degC at %.2f rad", lam * g, th0, bt); };
    p.lam_max = std::min(2e-3 / std::abs(g), dmax > 0 ? 0.35 * jam / (std::abs(g) * dmax) : inf);
  } else if (name == "moment_delay") {
    const double tau = signed_uniform(rng, 0.05, 1.0), revs = rng.chance(0.5) ? 0.0 : rng.uniform(0.25, 2.0);
    shape = {tau, revs};
    p.describe = [=](double lam) { return format("skew %.3f s, averaging %.2f revolutions", lam * tau, lam * revs); };
    p.lam_max = std::min(tau > 0 ? 5.0 / tau : 2.0 / -tau, revs > 0 ? 10.0 / revs : inf);
  } else if (name == "continuous_quarter_sums") {
    p.describe = [](double) { return std::string("continuous quarter sums (the switch's change, scaled)"); };
  } else if (name == "speed_drag") {
    const double a = rng.uniform(-kPi, kPi);
    shape = {a};
    p.describe = [=](double lam) { return format("%.4g kN·m per rpm at %.2f rad on (M_sy', M_sz')", lam, a); };
  } else {
    throw std::invalid_argument("unknown hidden effect " + name);
  }
  p.moments = member(name, model, jam, truth, std::move(shape));
  return p;
}

}  // namespace

const std::vector<HiddenEffectInfo>& hidden_effect_table() {
  static const std::vector<HiddenEffectInfo> t = {
      {"torque_gain", "T carried = (1 + g) T logged, |g| 1-5 % either sign (moments at the carried torque)", "torque", "any name containing 'torque'"},
      {"misalignment_offset", "unseen vector 0.02 lambda xi (at most 0.3 xi) at any direction, summed with the recorded one", "misalignment", "any name containing 'misalignment'"},
      {"twice_per_rev", "oval sleeve: A (cos, sin)(2 phi + p)", "order_2|spacing|2x|twice", "order_2*, spacing*, 2x, twice"},
      {"weight", "M_sy' lower by a constant", "weight", "any name containing 'weight'"},
      {"friction", "mu = 0.1 + lambda (mu0 + a T_ref/T + b zeta/xi - 0.1); mu0 0.02-0.3, a 0-0.15, b 0-0.3", "^friction$", "friction"},
      {"self_weight", "M_sy' -= (s - 1) (W_c + w_sh L_s / 2) L_s cos(gamma); s 0.5-0.9 or 1.1-2", "^(self_weight|channel_gain_offset)$", "self_weight, channel_gain_offset (one tilt: the same)"},
      {"pressure_angle_rotation", "shift s phi T/(T + T_s) for phi; s 0-1.5, T_s 0 (30 %) or 0-1.5 MN·m (x size)", "^pressure_angle_rotation$", "pressure_angle_rotation"},
      {"assembly_misalignment", "unseen vector zeta0 0.05-0.3 xi at any direction, summed", "^assembly_misalignment$", "assembly_misalignment"},
      {"eccentricity", "zeta_e (1 - (T/(s T_m))^k) along gravity below s T_m; zeta_e 0.05-0.3 xi, s 0.5-2, k 1 or 1-10, any direction; a torque staircase first", "^eccentricity$", "eccentricity"},
      {"compliance", "mesh stiffness r/(1 + r) of eq 5 (rim in series, r 1.5-20: 0.6-0.95)", "^compliance$", "compliance"},
      {"spacing_errors", "eq 11's z_o + e, e 5-50 um", "^spacing_errors$", "spacing_errors"},
      {"channel_gain_offset", "(1 + g) M + o per channel; g +-0.1, |o| 1-200 kN·m log-uniform (x size)", "^channel_gain_offset$", "channel_gain_offset"},
      {"hysteresis", "zeta_eff = max(0, zeta - d lag), d the true travel (sticky); lag 0.02-0.1 xi; misalignment sweeps first", "^hysteresis$", "hysteresis"},
      {"misalignment_scale", "zeta seen = (1 + k) zeta, |k| 0.03-0.2", "^misalignment_scale$", "misalignment_scale"},
      {"torque_calibration", "T carried = T (1 + k + c T / 1 MN·m), k, c +-0.05", "^torque_calibration$", "torque_calibration"},
      {"thermal_misalignment", "unseen vector g (theta - theta_0) along beta_t; |g| 2e-5-2e-4 rad/degC, theta_0 15-40 degC", "^thermal_misalignment$", "thermal_misalignment"},
      {"moment_delay", "moments M(t - tau), then averaged over N revolutions; |tau| 0.05-1 s, N 0 (50 %) or 0.25-2", "^moment_delay$", "moment_delay"},
      {"continuous_quarter_sums", "the continuous eqs 13, 42-43 instead of int(qN/4) (switch, change scaled)", "^continuous_quarter_sums$", "continuous_quarter_sums"},
      {"speed_drag", "c n (cos a, sin a) on (M_sy', M_sz'), any a; speed varied in every block", "speed", "any name containing 'speed' (expression's speed terms)"},
  };
  return t;
}

const std::vector<std::string>& hidden_effect_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> v;
    for (const auto& e : hidden_effect_table()) v.push_back(e.name);
    return v;
  }();
  return names;
}

std::string hidden_effect_pattern(const std::string& name) {
  for (const auto& e : hidden_effect_table()) {
    if (e.name == name) return e.pattern;
  }
  throw std::invalid_argument("unknown hidden effect " + name);
}

ProgrammeNeeds hidden_effect_programme(const std::string& name) {
  ProgrammeNeeds p;
  if (name == "eccentricity") p.first_block = 0;
  if (name == "hysteresis") p.first_block = 1;
  if (name == "speed_drag") p.vary_speed = true;
  return p;
}

std::string add_hidden_effect(const std::string& name, double snr, double level_nm, const CouplingModel& model,
                              double jam_rad, Channels& truth, Rng& rng) {
  const std::size_t n = truth.rows();
  if (name != "twice_per_rev" && name != "weight") {
    const Physical p = make_physical(name, model, jam_rad, truth, rng);
    const std::string what = apply_physical(p, snr * level_nm, truth);
    return format("%s (%s) at %.2fx the noise = %.3g kN·m rms", name.c_str(), what.c_str(), snr, snr * level_nm / 1e3);
  }
  // Additive signals, linear in their size by construction: the unit shape, scaled.
  std::vector<double> dy(n, 0.0), dz(n, 0.0);
  std::string what;
  if (name == "twice_per_rev") {
    const double p = rng.uniform(0, 2 * std::numbers::pi);
    double phi = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      if (i > 0) phi += 0.5 * (truth.speed_rpm[i] + truth.speed_rpm[i - 1]) * 2 * std::numbers::pi / 60.0 * (truth.time_s[i] - truth.time_s[i - 1]);
      dy[i] = std::cos(2 * phi + p);
      dz[i] = std::sin(2 * phi + p);
    }
    what = format("phase %.2f rad", p);
  } else if (name == "weight") {
    for (std::size_t i = 0; i < n; ++i) dy[i] = -1.0;
    what = "M_sy' offset";
  } else {
    throw std::invalid_argument("unknown hidden effect " + name);
  }
  double ss = 0.0;
  for (std::size_t i = 0; i < n; ++i) ss += dy[i] * dy[i] + dz[i] * dz[i];
  const double rms = std::sqrt(ss / (2.0 * n));
  const double k = rms > 0 ? snr * level_nm / rms : 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    truth.msy_nm[i] += k * dy[i];
    truth.msz_nm[i] += k * dz[i];
  }
  return format("%s (%s, scaled x%.3g) at %.2fx the noise = %.3g kN·m rms", name.c_str(), what.c_str(), k, snr, snr * level_nm / 1e3);
}

}  // namespace gc::zoo
