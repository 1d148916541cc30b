#include "diagnosis/recorded_channels.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>

#include "diagnosis/median.h"

namespace gc {
namespace {

using Reader = std::function<std::optional<double>(const RecordedSample&)>;

struct ChannelSpec {
  const char* name;
  const char* unit;
  bool measured;
  Reader read;
};

const std::vector<ChannelSpec>& channel_specs() {
  static const std::vector<ChannelSpec> specs = {
      {"msy", "N·m", true, [](const RecordedSample& s) { return std::optional<double>(s.measured.y_nm); }},
      {"msz", "N·m", true, [](const RecordedSample& s) { return std::optional<double>(s.measured.z_nm); }},
      {"torque", "N·m", false, [](const RecordedSample& s) { return std::optional<double>(s.input.torque_nm); }},
      {"misalignment", "rad", false, [](const RecordedSample& s) { return std::optional<double>(s.input.misalignment_rad); }},
      {"direction", "rad", false, [](const RecordedSample& s) { return std::optional<double>(s.input.direction_rad); }},
      {"speed", "rpm", false, [](const RecordedSample& s) { return s.input.speed_rpm; }},
      {"temperature", "deg C", false, [](const RecordedSample& s) { return s.input.temperature_c; }},
      {"hub_motion", "m", true, [](const RecordedSample& s) { return s.hub_motion_m; }},
  };
  return specs;
}

bool inputs_hold(const RecordedSample& a, const RecordedSample& b) {
  return a.input.torque_nm == b.input.torque_nm && a.input.misalignment_rad == b.input.misalignment_rad &&
         a.input.direction_rad == b.input.direction_rad;
}

/// Its changes carry noise, not only a programme's motion: where it moves, its second differences
/// are at least a twentieth of its first (white noise: sqrt(3) times; a probe's noise on a sweep:
/// 0.15 and more; a ramp: 0 but for rounding; a sine sampled 50 times a radian: 0.02).
bool moves_roughly(const std::vector<double>& values) {
  std::vector<double> first, second;
  for (std::size_t i = 2; i < values.size(); ++i) {
    const double d1 = values[i] - values[i - 1], d0 = values[i - 1] - values[i - 2];
    if (d1 == 0.0 && d0 == 0.0) continue;  // a hold
    first.push_back(std::abs(d1));
    second.push_back(std::abs(d1 - d0));
  }
  if (first.empty()) return false;
  return median(std::move(second)) >= 0.05 * median(std::move(first));
}

}  // namespace

std::vector<std::size_t> rows_in_time_order(std::span<const RecordedSample> observations) {
  std::vector<std::size_t> rows(observations.size());
  for (std::size_t i = 0; i < rows.size(); ++i) rows[i] = i;
  std::stable_sort(rows.begin(), rows.end(), [&](std::size_t a, std::size_t b) {
    return observations[a].input.time_s < observations[b].input.time_s;
  });
  return rows;
}

std::vector<RecordedChannel> recorded_channels(std::span<const RecordedSample> observations) {
  const std::vector<std::size_t> ordered = rows_in_time_order(observations);
  std::vector<RecordedChannel> channels;
  for (const ChannelSpec& spec : channel_specs()) {
    RecordedChannel channel{spec.name, spec.unit, ordered, {}, spec.measured};
    for (std::size_t r : ordered) {
      const std::optional<double> value = spec.read(observations[r]);
      if (!value || !std::isfinite(*value)) break;
      channel.values.push_back(*value);
    }
    if (!ordered.empty() && channel.values.size() == ordered.size()) channels.push_back(std::move(channel));
  }
  return channels;
}

bool changes_every_sample(const RecordedChannel& channel, std::span<const RecordedSample> observations) {
  constexpr std::size_t kFewestHolds = 20;
  std::size_t pairs = 0, ties = 0, hold_pairs = 0, hold_ties = 0;
  for (std::size_t i = 1; i < channel.values.size(); ++i) {
    const bool tie = channel.values[i] == channel.values[i - 1];
    ++pairs;
    ties += tie;
    if (inputs_hold(observations[channel.rows[i]], observations[channel.rows[i - 1]])) {
      ++hold_pairs;
      hold_ties += tie;
    }
  }
  if (pairs == 0) return false;
  if (channel.measured && hold_pairs >= kFewestHolds) return 2 * hold_ties < hold_pairs;
  if (channel.measured) {
    // The inputs move: a moment channel changes with them. Its longest run of one value is what is
    // judged, so it does not count itself: a bridge frozen for the second half of a recording is
    // not a channel that repeats by design (it gave "noise" at 34 kN·m against 3 kN·m of noise).
    std::size_t longest = 0;
    for (std::size_t i = 0, start = 0; i < channel.values.size(); ++i) {
      if (channel.values[i] != channel.values[start]) start = i;
      longest = std::max(longest, i - start);
    }
    return 2 * (ties - longest) < pairs - longest;
  }
  // An input that holds for half the recording and ramps smoothly the rest is a noise-free set
  // point, however many samples it changes on (a misalignment held while the direction turns).
  return 2 * ties < pairs && moves_roughly(channel.values);
}

double difference_sigma(const std::vector<double>& values) {
  if (values.size() < 2) return 0.0;
  std::vector<double> d;
  for (std::size_t i = 1; i < values.size(); ++i) d.push_back(std::abs(values[i] - values[i - 1]));
  double mean = 0.0;
  for (double x : d) mean += x;
  mean /= static_cast<double>(d.size());
  const double mad = median(std::move(d));
  return mad > 0.0 ? 1.4826 * mad / std::sqrt(2.0) : mean * std::sqrt(M_PI) / 2.0;
}

}  // namespace gc
