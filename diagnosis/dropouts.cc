#include "diagnosis/dropouts.h"

#include <algorithm>
#include <cmath>

#include "diagnosis/median.h"

namespace gc {
namespace {

constexpr std::size_t kNeighbours = 5;  ///< non-zero values either side that give the level

/// The median of the non-zero values nearest [start, end) on either side.
double level_around(const std::vector<double>& v, std::size_t start, std::size_t end) {
  std::vector<double> around;
  for (std::size_t i = start, k = 0; i > 0 && k < kNeighbours; --i) {
    if (v[i - 1] != 0.0) { around.push_back(v[i - 1]); ++k; }
  }
  for (std::size_t i = end, k = 0; i < v.size() && k < kNeighbours; ++i) {
    if (v[i] != 0.0) { around.push_back(v[i]); ++k; }
  }
  return median(std::move(around));
}

}  // namespace

std::optional<DataQualityFinding> zero_dropouts(const RecordedChannel& channel, const DataQualitySettings& settings) {
  const std::vector<double>& v = channel.values;
  std::vector<double> nonzero;
  for (double x : v) if (x != 0.0) nonzero.push_back(x);
  const double sigma = difference_sigma(nonzero);
  std::vector<std::size_t> rows;
  std::size_t runs = 0;
  for (std::size_t start = 0; start < v.size();) {
    if (v[start] != 0.0) { ++start; continue; }
    std::size_t end = start;
    while (end < v.size() && v[end] == 0.0) ++end;
    if (std::abs(level_around(v, start, end)) > settings.dropout_deviations * sigma) {
      for (std::size_t i = start; i < end; ++i) rows.push_back(channel.rows[i]);
      ++runs;
    }
    start = end;
  }
  if (rows.empty()) return std::nullopt;
  std::sort(rows.begin(), rows.end());
  DataQualityFinding finding{DataQualityKind::dropout, channel.name, rows, {}, true, ""};
  finding.detail = std::to_string(rows.size()) + " samples in " + std::to_string(runs) +
                   (runs == 1 ? " stretch" : " stretches") +
                   " read exactly 0 where the channel's level around them is far from zero: lost frames, not a "
                   "moment; excluded";
  return finding;
}

}  // namespace gc
