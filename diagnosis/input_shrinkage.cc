#include "diagnosis/input_shrinkage.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace gc {
namespace {

/// The rows of `rows` within a half-width of a row's time: positions [first, last).
struct Window {
  std::size_t first = 0, last = 0;
};

/// The centred window of each position k of `rows` with wanted[k]: half-width window_s / 2, or
/// less within that of the recording's ends, so that it stays centred (two pointers over time;
/// both bounds only move forward). A window cut short on one side is centred no more: at the first
/// row of a torque falling 650 kN·m in 0.75 s, the half window after it put its median 280 kN·m low.
std::vector<Window> centred_windows(std::span<const RecordedSample> observations, std::span<const std::size_t> rows,
                                    double window_s, const std::vector<bool>& wanted) {
  const auto time = [&](std::size_t k) { return observations[rows[k]].input.time_s; };
  std::vector<Window> out(rows.size());
  if (rows.empty()) return out;
  const double start = time(0), end = time(rows.size() - 1);
  std::size_t lo = 0, hi = 0;
  for (std::size_t k = 0; k < rows.size(); ++k) {
    if (!wanted[k]) continue;
    const double half = std::min({0.5 * window_s, time(k) - start, end - time(k)});
    while (time(lo) < time(k) - half) ++lo;
    hi = std::max(hi, k + 1);
    while (hi < rows.size() && time(hi) <= time(k) + half) ++hi;
    // As many rows either side: a rounding of the times must not put one more row on one side,
    // or a median beside a step takes the first row of the next stair.
    const std::size_t side = std::min(k - lo, hi - 1 - k);
    out[k] = {k - side, k + side + 1};
  }
  return out;
}

/// The mean of `value` over each wanted row's window, by running sums.
template <typename Value>
std::vector<double> centred_mean(std::span<const RecordedSample> observations, std::span<const std::size_t> rows,
                                 const std::vector<Window>& windows, Value value) {
  std::vector<double> sum(rows.size() + 1, 0.0);
  for (std::size_t k = 0; k < rows.size(); ++k) sum[k + 1] = sum[k] + value(observations[rows[k]].input);
  std::vector<double> mean(rows.size(), 0.0);
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const Window& w = windows[k];
    if (w.last > w.first) mean[k] = (sum[w.last] - sum[w.first]) / static_cast<double>(w.last - w.first);
  }
  return mean;
}

/// At most about this many rows of a window, evenly spaced, give its median: a window of 64 s at
/// 1 kHz then costs 63 values at every row, not 64,000.
constexpr std::size_t kMedianRows = 63;

/// The median of `value` over each wanted row's window (the row itself and every stride-th row
/// from it outwards, as many on either side: at most about kMedianRows of them).
template <typename Value>
std::vector<double> centred_median(std::span<const RecordedSample> observations, std::span<const std::size_t> rows,
                                   const std::vector<Window>& windows, Value value) {
  std::vector<double> median(rows.size(), 0.0), v;
  v.reserve(kMedianRows + 2);
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const Window& w = windows[k];
    if (w.last <= w.first) continue;
    const std::size_t stride = (w.last - w.first + kMedianRows - 1) / kMedianRows;
    const std::size_t each_side = (k - w.first) / stride;
    v.clear();
    v.push_back(value(observations[rows[k]].input));
    for (std::size_t m = 1; m <= each_side; ++m) {
      v.push_back(value(observations[rows[k - m * stride]].input));
      v.push_back(value(observations[rows[k + m * stride]].input));
    }
    const auto middle = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
    std::nth_element(v.begin(), middle, v.end());
    median[k] = *middle;
  }
  return median;
}

/// The centre of each wanted row's window: its mean, or its median where `s` says.
template <typename Value>
std::vector<double> centred_level(std::span<const RecordedSample> observations, std::span<const std::size_t> rows,
                                  const InputShrink& s, const std::vector<bool>& wanted, Value value) {
  const std::vector<Window> windows = centred_windows(observations, rows, s.window_s, wanted);
  return s.median ? centred_median(observations, rows, windows, value) : centred_mean(observations, rows, windows, value);
}

double shrunk_value(double x, double centre, const InputShrink& s) { return centre + s.keep * (x - centre); }

/// wanted[k]: row k of `rows` is one of `at` (both ascending); every row when `at` is empty.
std::vector<bool> wanted_positions(std::span<const std::size_t> rows, std::span<const std::size_t> at) {
  if (at.empty()) return std::vector<bool>(rows.size(), true);
  std::vector<bool> wanted(rows.size(), false);
  std::size_t j = 0;
  for (std::size_t k = 0; k < rows.size() && j < at.size(); ++k) {
    while (j < at.size() && at[j] < rows[k]) ++j;
    if (j < at.size() && at[j] == rows[k]) wanted[k] = true;
  }
  return wanted;
}

}  // namespace

std::vector<double> centred_medians(std::span<const RecordedSample> observations, std::span<const std::size_t> rows,
                                    double window_s, std::span<const std::size_t> at,
                                    double (*value)(const MeasurementSample&)) {
  const std::vector<bool> wanted = wanted_positions(rows, at);
  const std::vector<double> centres = centred_level(observations, rows, InputShrink{window_s, 0.0, true}, wanted, value);
  std::vector<double> out;
  out.reserve(at.size());
  for (std::size_t k = 0; k < rows.size(); ++k) {
    if (wanted[k]) out.push_back(centres[k]);
  }
  return out;
}

std::vector<RecordedSample> with_shrunk_inputs(std::span<const RecordedSample> observations,
                                               std::span<const std::size_t> rows, const InputShrinks& shrinks,
                                               std::span<const std::size_t> at) {
  InputShrinker shrinker(observations, rows, at);
  const std::span<const RecordedSample> out = shrinker.shrunk(shrinks);
  return {out.begin(), out.end()};
}

InputShrinker::InputShrinker(std::span<const RecordedSample> observations, std::span<const std::size_t> rows,
                             std::span<const std::size_t> at)
    : observations_(observations),
      rows_(rows),
      wanted_(wanted_positions(rows, at)),
      buffer_(observations.begin(), observations.end()) {}

const std::vector<double>& InputShrinker::centres(Channel channel, const InputShrink& shrink) {
  // A direction is averaged as a unit vector, never by a median (input_shrinkage.h).
  const bool median = shrink.median && (channel == kTorque || channel == kMisalignment);
  const auto key = std::make_tuple(channel, shrink.window_s, median);
  if (const auto found = centres_.find(key); found != centres_.end()) return found->second;
  InputShrink how = shrink;
  how.median = median;
  std::vector<double> m;
  switch (channel) {
    case kTorque:
      m = centred_level(observations_, rows_, how, wanted_, [](const MeasurementSample& s) { return s.torque_nm; });
      break;
    case kMisalignment:
      m = centred_level(observations_, rows_, how, wanted_, [](const MeasurementSample& s) { return s.misalignment_rad; });
      break;
    case kDirectionCos:
      m = centred_level(observations_, rows_, how, wanted_, [](const MeasurementSample& s) { return std::cos(s.direction_rad); });
      break;
    case kDirectionSin:
      m = centred_level(observations_, rows_, how, wanted_, [](const MeasurementSample& s) { return std::sin(s.direction_rad); });
      break;
  }
  return centres_.emplace(key, std::move(m)).first->second;
}

InputShrinker::Centres InputShrinker::centres_for(const InputShrinks& shrinks) {
  Centres m;
  if (!shrinks.torque.none()) m.torque = centres(kTorque, shrinks.torque).data();
  if (!shrinks.misalignment.none()) m.misalignment = centres(kMisalignment, shrinks.misalignment).data();
  if (!shrinks.direction.none()) {
    m.direction_cos = centres(kDirectionCos, shrinks.direction).data();
    m.direction_sin = centres(kDirectionSin, shrinks.direction).data();
  }
  return m;
}

void InputShrinker::write(const InputShrinks& shrinks, const Centres& m, std::size_t k) {
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
  // Every wanted row is written, shrunk or as recorded: the buffer holds an earlier trial's values.
  const Centres m = centres_for(shrinks);
  for (std::size_t k = 0; k < rows_.size(); ++k) {
    if (wanted_[k]) write(shrinks, m, k);
  }
  return buffer_;
}

std::span<const RecordedSample> InputShrinker::shrunk(const InputShrinks& shrinks, std::span<const std::size_t> read) {
  if (position_.empty()) {
    position_.assign(observations_.size(), rows_.size());
    for (std::size_t k = 0; k < rows_.size(); ++k) position_[rows_[k]] = k;
  }
  const Centres m = centres_for(shrinks);
  for (const std::size_t r : read) {
    if (position_[r] < rows_.size() && wanted_[position_[r]]) write(shrinks, m, position_[r]);
  }
  return buffer_;
}

}  // namespace gc
