#include "diagnosis/input_shrinkage.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace gc {
namespace {

/// The mean of `value` over the rows within window_s / 2 of each row's time, by running sums.
template <typename Value>
std::vector<double> centred_mean(std::span<const RecordedSample> observations, std::span<const std::size_t> rows,
                                 double window_s, Value value) {
  std::vector<double> sum(rows.size() + 1, 0.0);
  for (std::size_t k = 0; k < rows.size(); ++k) sum[k + 1] = sum[k] + value(observations[rows[k]].input);
  const auto time = [&](std::size_t k) { return observations[rows[k]].input.time_s; };
  std::vector<double> mean(rows.size());
  std::size_t lo = 0, hi = 0;
  for (std::size_t k = 0; k < rows.size(); ++k) {
    while (time(lo) < time(k) - 0.5 * window_s) ++lo;
    hi = std::max(hi, k + 1);
    while (hi < rows.size() && time(hi) <= time(k) + 0.5 * window_s) ++hi;
    mean[k] = (sum[hi] - sum[lo]) / static_cast<double>(hi - lo);
  }
  return mean;
}

double shrunk(double x, double mean, const InputShrink& s) { return mean + s.keep * (x - mean); }

}  // namespace

std::vector<RecordedSample> with_shrunk_inputs(std::span<const RecordedSample> observations,
                                               std::span<const std::size_t> rows, const InputShrinks& shrinks) {
  std::vector<RecordedSample> out(observations.begin(), observations.end());
  if (!shrinks.torque.none()) {
    const auto m = centred_mean(observations, rows, shrinks.torque.window_s,
                                [](const MeasurementSample& s) { return s.torque_nm; });
    for (std::size_t k = 0; k < rows.size(); ++k) {
      out[rows[k]].input.torque_nm = shrunk(observations[rows[k]].input.torque_nm, m[k], shrinks.torque);
    }
  }
  if (!shrinks.misalignment.none()) {
    const auto m = centred_mean(observations, rows, shrinks.misalignment.window_s,
                                [](const MeasurementSample& s) { return s.misalignment_rad; });
    for (std::size_t k = 0; k < rows.size(); ++k) {
      out[rows[k]].input.misalignment_rad =
          shrunk(observations[rows[k]].input.misalignment_rad, m[k], shrinks.misalignment);
    }
  }
  if (!shrinks.direction.none()) {
    // A direction is averaged as a unit vector; its departure from the mean is along the shorter arc.
    const double w = shrinks.direction.window_s;
    const auto c = centred_mean(observations, rows, w, [](const MeasurementSample& s) { return std::cos(s.direction_rad); });
    const auto s = centred_mean(observations, rows, w, [](const MeasurementSample& s) { return std::sin(s.direction_rad); });
    for (std::size_t k = 0; k < rows.size(); ++k) {
      if (c[k] == 0.0 && s[k] == 0.0) continue;
      const double beta = observations[rows[k]].input.direction_rad;
      const double mean = std::atan2(s[k], c[k]);
      out[rows[k]].input.direction_rad =
          mean + shrinks.direction.keep * std::remainder(beta - mean, 2.0 * std::numbers::pi);
    }
  }
  return out;
}

}  // namespace gc
