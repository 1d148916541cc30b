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

double shrunk_value(double x, double mean, const InputShrink& s) { return mean + s.keep * (x - mean); }

}  // namespace

std::vector<RecordedSample> with_shrunk_inputs(std::span<const RecordedSample> observations,
                                               std::span<const std::size_t> rows, const InputShrinks& shrinks) {
  InputShrinker shrinker(observations, rows);
  const std::span<const RecordedSample> out = shrinker.shrunk(shrinks);
  return {out.begin(), out.end()};
}

InputShrinker::InputShrinker(std::span<const RecordedSample> observations, std::span<const std::size_t> rows)
    : observations_(observations), rows_(rows), buffer_(observations.begin(), observations.end()) {}

const std::vector<double>& InputShrinker::means(Channel channel, double window_s) {
  const auto key = std::make_pair(channel, window_s);
  if (const auto found = means_.find(key); found != means_.end()) return found->second;
  std::vector<double> m;
  switch (channel) {
    case kTorque:
      m = centred_mean(observations_, rows_, window_s, [](const MeasurementSample& s) { return s.torque_nm; });
      break;
    case kMisalignment:
      m = centred_mean(observations_, rows_, window_s, [](const MeasurementSample& s) { return s.misalignment_rad; });
      break;
    case kDirectionCos:
      m = centred_mean(observations_, rows_, window_s, [](const MeasurementSample& s) { return std::cos(s.direction_rad); });
      break;
    case kDirectionSin:
      m = centred_mean(observations_, rows_, window_s, [](const MeasurementSample& s) { return std::sin(s.direction_rad); });
      break;
  }
  return means_.emplace(key, std::move(m)).first->second;
}

InputShrinker::Means InputShrinker::means_for(const InputShrinks& shrinks) {
  Means m;
  if (!shrinks.torque.none()) m.torque = means(kTorque, shrinks.torque.window_s).data();
  if (!shrinks.misalignment.none()) m.misalignment = means(kMisalignment, shrinks.misalignment.window_s).data();
  if (!shrinks.direction.none()) {
    m.direction_cos = means(kDirectionCos, shrinks.direction.window_s).data();
    m.direction_sin = means(kDirectionSin, shrinks.direction.window_s).data();
  }
  return m;
}

void InputShrinker::write(const InputShrinks& shrinks, const Means& m, std::size_t k) {
  const MeasurementSample& in = observations_[rows_[k]].input;
  MeasurementSample& out = buffer_[rows_[k]].input;
  out.torque_nm = m.torque ? shrunk_value(in.torque_nm, m.torque[k], shrinks.torque) : in.torque_nm;
  out.misalignment_rad =
      m.misalignment ? shrunk_value(in.misalignment_rad, m.misalignment[k], shrinks.misalignment) : in.misalignment_rad;
  out.direction_rad = in.direction_rad;
  if (!m.direction_cos) return;
  // A direction is averaged as a unit vector; its departure from the mean is along the shorter arc.
  const double c = m.direction_cos[k], s = m.direction_sin[k];
  if (c == 0.0 && s == 0.0) return;
  const double mean = std::atan2(s, c);
  out.direction_rad = mean + shrinks.direction.keep * std::remainder(in.direction_rad - mean, 2.0 * std::numbers::pi);
}

std::span<const RecordedSample> InputShrinker::shrunk(const InputShrinks& shrinks) {
  // Every listed row is written, shrunk or as recorded: the buffer holds an earlier trial's values.
  const Means m = means_for(shrinks);
  for (std::size_t k = 0; k < rows_.size(); ++k) write(shrinks, m, k);
  return buffer_;
}

std::span<const RecordedSample> InputShrinker::shrunk(const InputShrinks& shrinks, std::span<const std::size_t> read) {
  if (position_.empty()) {
    position_.assign(observations_.size(), rows_.size());
    for (std::size_t k = 0; k < rows_.size(); ++k) position_[rows_[k]] = k;
  }
  const Means m = means_for(shrinks);
  for (const std::size_t r : read) {
    if (position_[r] < rows_.size()) write(shrinks, m, position_[r]);
  }
  return buffer_;
}

}  // namespace gc
