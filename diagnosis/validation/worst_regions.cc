#include "diagnosis/validation/worst_regions.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

#include "core/engineering_text.h"

namespace gc {
namespace {

constexpr double kDegreesPerRadian = 180.0 / std::numbers::pi;

int populated_bins(const ErrorBinning& binning, std::size_t min_count) {
  return static_cast<int>(std::count_if(binning.bins().begin(), binning.bins().end(),
                                        [min_count](const ErrorBin& bin) {
                                          return bin.errors.count() >= min_count;
                                        }));
}

// RMSE of everything outside `bin`, from the totals: sum of squares minus the bin's.
double rmse_outside(const ErrorMetrics& all, const ErrorMetrics& bin) {
  const double outside_count = static_cast<double>(all.count - bin.count);
  if (outside_count <= 0.0) return 0.0;
  const double sse = all.rmse_nm * all.rmse_nm * static_cast<double>(all.count) -
                     bin.rmse_nm * bin.rmse_nm * static_cast<double>(bin.count);
  return std::sqrt(std::max(0.0, sse) / outside_count);
}

double contrast(const ErrorMetrics& all, const ErrorMetrics& bin) {
  const double outside = rmse_outside(all, bin);
  // A floor of a millionth of the overall RMSE keeps a perfect fit outside the bin finite.
  return bin.rmse_nm / std::max(outside, 1e-6 * all.rmse_nm + 1e-300);
}

std::string level_word(double position, const char* low, const char* mid, const char* high) {
  return position < 1.0 / 3.0 ? low : position > 2.0 / 3.0 ? high : mid;
}

// Where bin `index` lies in its binning's fixed span (torque 0 .. torque_span x T_ref,
// misalignment 0 .. xi): from the edges, not from the inputs seen, so that a bin gets the same
// word in a whole recording (validate) and in any window of it (the live monitor).
double bin_position(const ErrorBinning& binning, std::size_t index) {
  const std::vector<ErrorBin>& bins = binning.bins();
  const double lowest = bins.front().lower, span = bins.back().upper - lowest;
  const ErrorBin& bin = bins[index];
  return span > 0.0 ? (0.5 * (bin.lower + bin.upper) - lowest) / span : 0.5;
}

std::string printf_string(const char* format, double a, double b) {
  char text[96];
  std::snprintf(text, sizeof text, format, a, b);
  return text;
}

}  // namespace

std::vector<RegionError> worst_regions(const ValidationAccumulator& validation, Channel channel,
                                       double min_share) {
  const ErrorMetrics overall = validation.overall()[channel].metrics();
  const auto min_count = std::max<std::size_t>(
      10, static_cast<std::size_t>(min_share * static_cast<double>(overall.count)));
  std::vector<RegionError> regions;
  for (const ErrorBinning& binning : validation.binnings()) {
    if (populated_bins(binning, min_count) < 2) continue;
    std::optional<RegionError> worst;
    for (std::size_t i = 0; i < binning.bins().size(); ++i) {
      const ErrorBin& bin = binning.bins()[i];
      if (bin.errors.count() < min_count) continue;
      const ErrorMetrics metrics = bin.errors[channel].metrics();
      if (worst && metrics.rmse_nm <= worst->metrics.rmse_nm) continue;
      worst = RegionError{binning.dimension(), channel, i, bin, metrics, overall,
                          contrast(overall, metrics), bin_position(binning, i)};
    }
    if (worst) regions.push_back(*worst);
  }
  // Time last: in a designed load sequence every input is a function of time, so a time bin
  // repeats what a load input says more plainly; it leads only for drift (no other region).
  std::stable_sort(regions.begin(), regions.end(), [](const RegionError& a, const RegionError& b) {
    const bool a_time = a.dimension == BinDimension::time, b_time = b.dimension == BinDimension::time;
    return a_time != b_time ? b_time : a.contrast > b.contrast;
  });
  return regions;
}

double explained_share(const ErrorBinning& binning, const ErrorMetrics& overall,
                       Channel channel) {
  const double total = overall.rmse_nm * overall.rmse_nm * static_cast<double>(overall.count);
  if (total <= 0.0) return 0.0;
  double explained = 0.0;
  for (const ErrorBin& bin : binning.bins()) {
    const ErrorMetrics m = bin.errors[channel].metrics();
    const double deviation = m.bias_nm - overall.bias_nm;
    explained += static_cast<double>(m.count) * deviation * deviation;
  }
  return std::clamp(explained / total, 0.0, 1.0);
}

ErrorSignature error_signature(const ValidationAccumulator& validation, Channel channel) {
  const ErrorMetrics overall = validation.overall()[channel].metrics();
  ErrorSignature signature{channel};
  signature.noise_estimate_nm = validation.noise_estimate_nm(channel);
  const double noise_sq = signature.noise_estimate_nm * signature.noise_estimate_nm;
  signature.systematic_rms_nm = std::sqrt(std::max(0.0, overall.rmse_nm * overall.rmse_nm - noise_sq));
  // Below a third of the noise the systematic part adds under 6 % to the RMSE.
  signature.at_noise_level =
      signature.systematic_rms_nm < kAtNoiseLevelShare * signature.noise_estimate_nm;
  for (std::size_t d = 0; d < kBinDimensions.size(); ++d) {
    signature.explained_share[d] = explained_share(validation.binnings()[d], overall, channel);
  }
  return signature;
}

std::string describe_region(const RegionError& r) {
  const ErrorBin& bin = r.region;
  switch (r.dimension) {
    case BinDimension::torque:
      // kN·m whatever the torque, as the moments of describe() and the dashboard.
      return level_word(r.position, "low", "medium", "high") + " torque (" +
             engineering_range(bin.seen_min, bin.seen_max, "N·m", 1e3) + ")";
    case BinDimension::misalignment:
      return level_word(r.position, "small", "medium", "large") + " misalignment (" +
             engineering_range(bin.seen_min * kDegreesPerRadian, bin.seen_max * kDegreesPerRadian,
                               "deg") + ")";
    case BinDimension::direction:
      return "misalignment direction" +
             printf_string(" %.0f to %.0f deg", bin.lower * kDegreesPerRadian,
                           bin.upper * kDegreesPerRadian);
    case BinDimension::loading:
      return bin.seen_min > 0.5   ? "rising misalignment"
             : bin.seen_max < -0.5 ? "falling misalignment"
                                   : "steady misalignment";
    case BinDimension::time:
      return "time " + engineering_range(bin.seen_min, bin.seen_max, "s");
  }
  return "";
}

std::string describe(const RegionError& r) {
  // Bias and both RMSEs under one prefix, read side by side.
  const double reference = std::max(r.metrics.rmse_nm, r.overall.rmse_nm);
  return std::string(to_string(r.channel)) + " errs most at " + describe_region(r) + ": bias " +
         (r.metrics.bias_nm >= 0.0 ? "+" : "") +
         engineering_text(r.metrics.bias_nm, "N·m", reference) + ", RMSE " +
         engineering_text(r.metrics.rmse_nm, "N·m", reference) + " in " +
         std::to_string(r.metrics.count) + " samples, against " +
         engineering_text(r.overall.rmse_nm, "N·m", reference) + " overall";
}

}  // namespace gc
