// The regions where a model errs most, and their description in words, e.g.
//   "M_sz' errs most at low torque (0.15-0.30 MN·m): bias +42 kN·m, RMSE 50 kN·m (3.3 % of
//    T_ref) in 1200 samples, against 12 kN·m overall".
#pragma once

#include <array>
#include <string>
#include <vector>

#include "core/validation/error_bins.h"

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
  double position = 0.0;   ///< where the region lies in the range seen: 0 lowest, 1 highest
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

/// The error of one channel split into noise and a systematic part.
struct ErrorSignature {
  Channel channel;
  double noise_estimate_nm = 0.0;    ///< ValidationAccumulator::noise_estimate_nm
  double systematic_rms_nm = 0.0;    ///< sqrt(max(0, RMSE^2 - noise^2))
  bool at_noise_level = false;       ///< the systematic part is below a third of the noise
  std::array<double, kBinDimensions.size()> explained_share{};  ///< per kBinDimensions
};
ErrorSignature error_signature(const ValidationAccumulator& validation, Channel channel);

/// One sentence naming the region in words, with its bias and RMSE in engineering units
/// (core/engineering_text.h), e.g. "bias +18.2 kN·m, RMSE 20.4 kN·m".
std::string describe(const RegionError& region);
/// The region alone, e.g. "low torque (150-300 kN·m)", "rising misalignment".
std::string describe_region(const RegionError& region);

}  // namespace gc
