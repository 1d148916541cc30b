#include "diagnosis/quantisation.h"

#include <algorithm>
#include <cmath>

#include "core/engineering_text.h"

namespace gc {
namespace {

constexpr double kWholeShare = 0.9;   ///< of the gaps that must be whole multiples of the step
constexpr double kStepTolerance = 0.02;  ///< of a step: the printed values' rounding
constexpr double kLeastLevels = 8.0;     ///< steps a channel's range spans before it is called a grid
constexpr double kMostStepShare = 50.0;  ///< of the noise: a coarser "grid" is set points held without noise

bool whole_multiples(const std::vector<double>& gaps, double step) {
  std::size_t whole = 0;
  for (double g : gaps) {
    const double multiple = g / step;
    whole += std::abs(multiple - std::round(multiple)) <= kStepTolerance;
  }
  return static_cast<double>(whole) >= kWholeShare * static_cast<double>(gaps.size());
}

}  // namespace

std::optional<double> quantisation_step(const std::vector<double>& values) {
  std::vector<double> distinct = values;
  std::sort(distinct.begin(), distinct.end());
  if (distinct.size() < 3) return std::nullopt;
  // Values a few ulps apart are one level written two ways (0.3 and 0.30000000000000004).
  const double same = 1e-9 * std::max(std::abs(distinct.front()), std::abs(distinct.back()));
  distinct.erase(std::unique(distinct.begin(), distinct.end(), [&](double a, double b) { return b - a <= same; }),
                 distinct.end());
  if (distinct.size() < 3 || 2 * distinct.size() > values.size()) return std::nullopt;
  std::vector<double> gaps;
  for (std::size_t i = 1; i < distinct.size(); ++i) gaps.push_back(distinct[i] - distinct[i - 1]);
  const double smallest = *std::min_element(gaps.begin(), gaps.end());
  for (int divisor = 1; divisor <= 4; ++divisor) {
    if (whole_multiples(gaps, smallest / divisor)) return smallest / divisor;
  }
  return std::nullopt;
}

std::optional<DataQualityFinding> coarse_quantisation(const RecordedChannel& channel, const DataQualitySettings& settings) {
  const std::optional<double> step = quantisation_step(channel.values);
  const double sigma = difference_sigma(channel.values);
  if (!step || !(sigma > 0.0) || *step < settings.coarse_step_share * sigma) return std::nullopt;
  // A grid spans many levels; a few set points held without noise (moments 10 kN·m apart at three
  // torques) are levels, not an ADC's steps.
  const auto [low, high] = std::minmax_element(channel.values.begin(), channel.values.end());
  if (*high - *low < kLeastLevels * *step) return std::nullopt;
  // A step many times the noise is set points held without noise (a moment of -0.1 T at each torque
  // of a staircase), not a converter's grid, which the noise dithers across a few steps.
  if (*step > kMostStepShare * sigma) return std::nullopt;
  const double rounding = *step / std::sqrt(12.0);
  DataQualityFinding finding{DataQualityKind::quantisation, channel.name, {}, {}, false, ""};
  finding.detail = "values on a grid of " + engineering_text(*step, channel.unit) + " (the ADC step), " +
                   std::to_string(static_cast<int>(std::lround(100.0 * *step / sigma))) +
                   " % of the channel's noise (" + engineering_text(sigma, channel.unit, sigma) +
                   "): rounding adds " + engineering_text(rounding, channel.unit, sigma) +
                   " of white noise and makes identical neighbours common, so a median-based noise scale "
                   "moves in steps; kept";
  return finding;
}

}  // namespace gc
