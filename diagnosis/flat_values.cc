#include "diagnosis/flat_values.h"

#include <algorithm>
#include <cmath>

#include "core/engineering_text.h"

namespace gc {
namespace {

/// The rows (ascending) at `positions` of the channel.
std::vector<std::size_t> rows_at(const RecordedChannel& channel, const std::vector<std::size_t>& positions) {
  std::vector<std::size_t> rows;
  for (std::size_t p : positions) rows.push_back(channel.rows[p]);
  std::sort(rows.begin(), rows.end());
  return rows;
}

/// Positions at `rail` when it piles up against the next value inward (`inward`: toward the middle).
std::vector<std::size_t> rail_positions(const std::vector<double>& values, double rail, bool inward_is_lower,
                                        const DataQualitySettings& settings) {
  std::vector<std::size_t> at;
  double next = inward_is_lower ? -INFINITY : INFINITY;
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (values[i] == rail) at.push_back(i);
    else next = inward_is_lower ? std::max(next, values[i]) : std::min(next, values[i]);
  }
  const auto at_next = static_cast<double>(std::count(values.begin(), values.end(), next));
  if (at.size() < settings.shortest_rail || static_cast<double>(at.size()) < settings.rail_pile_up * at_next) return {};
  return at;
}

}  // namespace

std::optional<DataQualityFinding> clipped_samples(const RecordedChannel& channel, const DataQualitySettings& settings) {
  if (channel.values.empty()) return std::nullopt;
  const auto [low, high] = std::minmax_element(channel.values.begin(), channel.values.end());
  if (*low == *high) return std::nullopt;
  std::vector<std::size_t> positions = rail_positions(channel.values, *high, true, settings);
  std::string where = positions.empty() ? "" : "its maximum " + engineering_text(*high, channel.unit);
  const std::vector<std::size_t> lower = rail_positions(channel.values, *low, false, settings);
  if (!lower.empty()) {
    where += (where.empty() ? "" : " and ") + std::string("its minimum ") + engineering_text(*low, channel.unit);
    positions.insert(positions.end(), lower.begin(), lower.end());
  }
  if (positions.empty()) return std::nullopt;
  DataQualityFinding finding{DataQualityKind::clipped, channel.name, rows_at(channel, positions), {}, true, ""};
  finding.detail = std::to_string(positions.size()) + " samples sit exactly at " + where +
                   ", piled up where a tail thins out: the channel at its rail (amplifier or ADC range), "
                   "not the coupling's moment; excluded";
  return finding;
}

std::optional<DataQualityFinding> stuck_runs(const RecordedChannel& channel, const std::vector<bool>& taken,
                                             const DataQualitySettings& settings) {
  const std::vector<double>& v = channel.values;
  const std::size_t n = v.size();
  if (n < 2) return std::nullopt;
  std::size_t ties = 0;
  for (std::size_t i = 1; i < n; ++i) ties += v[i] == v[i - 1];
  const double p = static_cast<double>(ties) / static_cast<double>(n - 1);
  // n p^(L-1) < chance: the longest run chance explains.
  const double explained = p > 0.0 ? 1.0 + std::log(settings.stuck_chance / static_cast<double>(n)) / std::log(p) : 1.0;
  const double shortest = std::max(static_cast<double>(settings.shortest_stuck_run), std::floor(explained) + 1.0);
  std::vector<std::size_t> positions;
  std::size_t runs = 0, longest = 0;
  for (std::size_t start = 0; start < n;) {
    std::size_t end = start + 1;
    while (end < n && v[end] == v[start]) ++end;
    std::vector<std::size_t> run;
    for (std::size_t i = start; i < end; ++i) if (!taken[i]) run.push_back(i);
    if (static_cast<double>(run.size()) >= shortest) {
      positions.insert(positions.end(), run.begin(), run.end());
      ++runs;
      longest = std::max(longest, run.size());
    }
    start = end;
  }
  if (positions.empty()) return std::nullopt;
  DataQualityFinding finding{DataQualityKind::stuck, channel.name, rows_at(channel, positions), {}, true, ""};
  finding.detail = std::to_string(runs) + (runs == 1 ? " run" : " runs") + " of identical values (longest " +
                   std::to_string(longest) + " samples) where the channel's ties (" +
                   std::to_string(static_cast<int>(std::lround(100.0 * p))) + " % of neighbours) explain at most " +
                   std::to_string(static_cast<int>(shortest) - 1) + ": a frozen reading; excluded";
  return finding;
}

std::vector<bool> positions_of(const RecordedChannel& channel, const std::vector<std::size_t>& rows) {
  std::vector<bool> taken(channel.rows.size(), false);
  for (std::size_t i = 0; i < channel.rows.size(); ++i) {
    taken[i] = std::binary_search(rows.begin(), rows.end(), channel.rows[i]);
  }
  return taken;
}

}  // namespace gc
