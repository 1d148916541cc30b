// The regions where a model errs most, and their description in words, e.g.
//   "M_sz' errs most at low torque (150-300 kN·m): bias +42 kN·m, RMSE 50 kN·m in 1200
//    samples, against 12 kN·m overall".
#pragma once

#include <array>
#include <string>
#include <vector>

#include "diagnosis/validation/error_bins.h"

namespace gc {

struct RegionError {
  BinDimension dimension;
  Channel channel;
  std::size_t bin = 0;     ///< index in the dimension's binning
  ErrorBin region;         ///< its edges and the inputs seen in it
  ErrorMetrics metrics;    ///< the channel's error in the region
  ErrorMetrics overall;    ///< the channel's error over the whole recording
  /// How much larger the region's RMSE is than that of the rest of the recording; regions are
  /// ranked by it, so a uniform error names no region in particular (contrast near 1).
  double contrast = 1.0;
  /// Where the bin lies in its binning's fixed span (torque 0 .. torque_span x T_ref,
  /// misalignment 0 .. xi): 0 lowest, 1 highest. From the bin's edges, not from the inputs
  /// seen, so the same bin gets the same word (describe_region) in validate's whole recording
  /// and in the live monitor's window.
  double position = 0.0;
};

/// For `channel`, the worst bin of every dimension with more than one populated bin, worst
/// first (time last: see worst_regions.cc). A bin counts when it holds at least `min_share` of the samples (and 10 or more),
/// so a handful of samples cannot name a region.
std::vector<RegionError> worst_regions(const ValidationAccumulator& validation, Channel channel,
                                       double min_share = 0.02);

/// How much of `channel`'s mean-square error the bin biases of `dimension` explain beyond the
/// overall bias: sum_b n_b (bias_b - bias)^2 / sum e^2, in [0, 1]. Near 1: the error is a
/// systematic function of that input; near 0: not (noise, a uniform bias, or an error whose
/// sign another input sets).
double explained_share(const ErrorBinning& binning, const ErrorMetrics& overall, Channel channel);

/// A channel's error is at the noise level while its systematic part is below this share of
/// the noise: then the model's part of the mean-square error is under 10 % (the RMSE under
/// 1.054 x the noise). The monitor's at_noise_level and the dashboard's green badge.
inline constexpr double kAtNoiseLevelShare = 1.0 / 3.0;

/// The error of one channel split into noise and a systematic part.
struct ErrorSignature {
  Channel channel;
  double noise_estimate_nm = 0.0;    ///< ValidationAccumulator::noise_estimate_nm
  double systematic_rms_nm = 0.0;    ///< sqrt(max(0, RMSE^2 - noise^2))
  bool at_noise_level = false;       ///< systematic part < kAtNoiseLevelShare x noise
  std::array<double, kBinDimensions.size()> explained_share{};  ///< per kBinDimensions
};
ErrorSignature error_signature(const ValidationAccumulator& validation, Channel channel);

/// One sentence naming the region in words, with its bias and RMSE in engineering units
/// (core/engineering_text.h), e.g. "bias +18.2 kN·m, RMSE 20.4 kN·m".
std::string describe(const RegionError& region);
/// The region alone, e.g. "low torque (150-300 kN·m)", "rising misalignment": the one place
/// that names a bin, for validate, diagnose and the live monitor (hence the dashboard). Torque
/// and misalignment bins are "low"/"small" in the lower third of the binning's span (below
/// 0.53 T_ref, below xi / 3), "high"/"large" in the upper third, "medium" between; the range
/// in parentheses is the inputs seen in the bin, torques always in kN·m.
std::string describe_region(const RegionError& region);

}  // namespace gc
