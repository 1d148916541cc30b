#include "diagnosis/separating_experiment.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <optional>
#include <sstream>
#include <vector>

#include "core/model_error.h"
#include "diagnosis/median.h"

namespace gc {
namespace {

double median_of(std::span<const RecordedSample> observations, std::span<const std::size_t> rows,
                 double (*read)(const MeasurementSample&)) {
  std::vector<double> v;
  for (std::size_t r : rows) v.push_back(read(observations[r].input));
  return median(std::move(v));
}

/// a - b at one sample, or nullopt when either model cannot predict it.
std::optional<Eigen::Vector2d> difference(const CouplingModel& a, const CouplingModel& b, const MeasurementSample& s) {
  try {
    const SensorMoments ma = a.predict(s).moments, mb = b.predict(s).moments;
    return Eigen::Vector2d(ma.y_nm - mb.y_nm, ma.z_nm - mb.z_nm);
  } catch (const ModelError&) {
    return std::nullopt;
  }
}

struct Sweep {
  std::string input, unit;
  std::vector<double> values;
  std::function<void(MeasurementSample&, double)> set;
};

/// The recorded range of an optional input over `rows`, or nullopt when a row lacks it.
std::optional<std::pair<double, double>> recorded_range(std::span<const RecordedSample> observations,
                                                        std::span<const std::size_t> rows,
                                                        std::optional<double> MeasurementSample::*input) {
  std::pair<double, double> range{INFINITY, -INFINITY};
  for (std::size_t r : rows) {
    const std::optional<double>& v = observations[r].input.*input;
    if (!v) return std::nullopt;
    range = {std::min(range.first, *v), std::max(range.second, *v)};
  }
  return range;
}

/// Every input a candidate can depend on: torque, misalignment, direction, loading direction, and
/// speed and temperature where the recording has them (a thermal growth and an assembly offset part
/// only as the oil warms, so an experiment that leaves temperature out cannot tell them apart).
std::vector<Sweep> sweeps(const CouplingModel& model, double max_torque, std::span<const RecordedSample> observations,
                          std::span<const std::size_t> rows) {
  std::vector<Sweep> out(4);
  out[0] = {"torque", "N·m", {}, [](MeasurementSample& s, double v) { s.torque_nm = v; }};
  out[1] = {"misalignment", "rad", {}, [](MeasurementSample& s, double v) { s.misalignment_rad = v; }};
  out[2] = {"direction", "rad", {}, [](MeasurementSample& s, double v) { s.direction_rad = v; }};
  // A sample moving one way has travelled that way (hysteresis reads the travel, held in a hold).
  out[3] = {"loading_direction", "-", {-1, 0, 1}, [](MeasurementSample& s, double v) {
              s.loading_direction = static_cast<int>(v);
              s.travel_direction = static_cast<int>(v);
            }};
  const double jam = model.geometry().jam_angle().angle_rad;
  for (int k = 0; k <= 24; ++k) {
    out[0].values.push_back(max_torque * (0.1 + 1.4 * k / 24.0));
    out[1].values.push_back(0.9 * jam * k / 24.0);
    out[2].values.push_back(2 * std::numbers::pi * k / 24.0);
  }
  // Beyond the recorded range by half of it (at least 20 deg C, or 0 to 1.5 times the top speed).
  if (const auto t = recorded_range(observations, rows, &MeasurementSample::temperature_c)) {
    const double margin = std::max(20.0, 0.5 * (t->second - t->first));
    Sweep sweep{"temperature", "deg C", {}, [](MeasurementSample& s, double v) { s.temperature_c = v; }};
    for (int k = 0; k <= 24; ++k) sweep.values.push_back(t->first - margin + (t->second - t->first + 2 * margin) * k / 24.0);
    out.push_back(std::move(sweep));
  }
  if (const auto n = recorded_range(observations, rows, &MeasurementSample::speed_rpm)) {
    Sweep sweep{"speed", "rpm", {}, [](MeasurementSample& s, double v) { s.speed_rpm = v; }};
    for (int k = 0; k <= 24; ++k) sweep.values.push_back(1.5 * std::max(n->second, 1.0) * k / 24.0);
    out.push_back(std::move(sweep));
  }
  return out;
}

/// The same models on the same coupling tilted (eq 48's gamma) from its own tilt to 30 deg more:
/// a property of the test rig rather than a recorded input, but what tells a weight from an offset.
SeparatingExperiment tilt_experiment(const CouplingModel& a, const CouplingModel& b,
                                     const MeasurementSample& reference, const Eigen::Vector2d& offset) {
  SeparatingExperiment best;
  for (int k = 1; k <= 6; ++k) {
    CouplingDefinition tilted = a.base_coupling();
    tilted.tilt_rad += k * 5.0 * std::numbers::pi / 180.0;
    try {
      const CouplingModel ta(tilted, a.effects(), a.options()), tb(tilted, b.effects(), b.options());
      const auto d = difference(ta, tb, reference);
      if (d && (*d - offset).norm() > best.difference_nm) best = {"tilt", tilted.tilt_rad, (*d - offset).norm(), ""};
    } catch (const ModelError&) {
      // a tilt the coupling does not accept: not a usable experiment
    }
  }
  return best;
}

}  // namespace

SeparatingExperiment separating_experiment(const CouplingModel& a, const CouplingModel& b,
                                           std::span<const RecordedSample> observations,
                                           std::span<const std::size_t> rows, double noise_sigma_nm) {
  SeparatingExperiment best;
  if (rows.empty()) return best;
  MeasurementSample reference = observations[rows[0]].input;
  reference.torque_nm = median_of(observations, rows, [](const MeasurementSample& s) { return s.torque_nm; });
  reference.misalignment_rad = median_of(observations, rows, [](const MeasurementSample& s) { return s.misalignment_rad; });
  double max_torque = 0.0;
  for (std::size_t r : rows) max_torque = std::max(max_torque, observations[r].input.torque_nm);
  const std::optional<Eigen::Vector2d> at_reference = difference(a, b, reference);
  const Eigen::Vector2d offset = at_reference ? *at_reference : Eigen::Vector2d::Zero();
  std::string unit;
  for (const Sweep& sweep : sweeps(a, max_torque, observations, rows)) {
    for (double v : sweep.values) {
      MeasurementSample s = reference;
      sweep.set(s, v);
      const auto d = difference(a, b, s);
      if (d && (*d - offset).norm() > best.difference_nm) {
        best = {sweep.input, v, (*d - offset).norm(), ""};
        unit = sweep.unit;
      }
    }
  }
  std::ostringstream advice;
  advice.precision(3);
  const double noise = std::max(noise_sigma_nm, 1e-300);
  if (best.difference_nm > 3.0 * noise_sigma_nm) {
    advice << "a sweep of " << best.input << " out to " << best.value << " " << unit
           << " would separate them: their predictions part by " << best.difference_nm << " N·m there, "
           << best.difference_nm / noise << " times the noise";
  } else if (const SeparatingExperiment tilt = tilt_experiment(a, b, reference, offset);
             tilt.difference_nm > 3.0 * noise_sigma_nm) {
    best = tilt;
    advice << "no sweep of the recorded inputs separates them, but a test at a shaft tilt of "
           << best.value * 180.0 / std::numbers::pi << " deg would: their predictions part by "
           << best.difference_nm << " N·m there, " << best.difference_nm / noise << " times the noise";
  } else {
    best.input.clear();
    advice << "no sweep of the recorded inputs (torque, misalignment, direction, loading direction, and speed and "
              "temperature where recorded) or of shaft tilt separates them "
              "(their predictions stay within 3 noise sigma); change what they depend on outside the recording";
  }
  best.advice = advice.str();
  return best;
}

}  // namespace gc
