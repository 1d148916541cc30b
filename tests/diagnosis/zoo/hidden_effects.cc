#include "tests/diagnosis/zoo/hidden_effects.h"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "tests/diagnosis/zoo/text.h"

namespace gc::zoo {
namespace {

MeasurementSample sample(const Channels& c, std::size_t i) {
  MeasurementSample s;
  s.time_s = c.time_s[i];
  s.torque_nm = c.torque_nm[i];
  s.misalignment_rad = c.zeta_rad[i];
  s.direction_rad = c.beta_rad[i];
  s.speed_rpm = c.speed_rpm[i];
  s.temperature_c = c.temperature_c[i];
  return s;
}

}  // namespace

const std::vector<std::string>& hidden_effect_names() {
  static const std::vector<std::string> names = {"torque_gain", "misalignment_offset", "twice_per_rev", "weight"};
  return names;
}

std::string hidden_effect_pattern(const std::string& name) {
  if (name == "torque_gain") return "torque";
  if (name == "misalignment_offset") return "misalignment";
  if (name == "twice_per_rev") return "order_2|spacing|2x|twice";
  if (name == "weight") return "weight";
  throw std::invalid_argument("unknown hidden effect " + name);
}

std::string add_hidden_effect(const std::string& name, double snr, double level_nm, const CouplingModel& model,
                              double jam_rad, Channels& truth, Rng& rng) {
  const std::size_t n = truth.rows();
  std::vector<double> dy(n, 0.0), dz(n, 0.0);
  std::string what;
  if (name == "torque_gain" || name == "misalignment_offset") {
    // The change at a small trial size, then scaled: linear in the size to first order.
    const double beta0 = rng.uniform(-std::numbers::pi, std::numbers::pi);
    for (std::size_t i = 0; i < n; ++i) {
      MeasurementSample s = sample(truth, i);
      if (name == "torque_gain") {
        s.torque_nm *= 1.01;
      } else {
        const double x = s.misalignment_rad * std::cos(s.direction_rad) + 0.02 * jam_rad * std::cos(beta0);
        const double y = s.misalignment_rad * std::sin(s.direction_rad) + 0.02 * jam_rad * std::sin(beta0);
        s.misalignment_rad = std::hypot(x, y);
        s.direction_rad = s.direction_rad + std::remainder(std::atan2(y, x) - s.direction_rad, 2 * std::numbers::pi);
      }
      const SensorMoments m = model.predict(s).moments;
      dy[i] = m.y_nm - truth.msy_nm[i];
      dz[i] = m.z_nm - truth.msz_nm[i];
    }
    what = name == "torque_gain" ? "gain 1 %% trial" : format("offset 2 %% of jam trial at %.2f rad", beta0);
  } else if (name == "twice_per_rev") {
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
