// The ADC step of a channel, from the gaps between its distinct values: every gap a whole multiple
// of one step. Rounding to a step q adds q / sqrt(12) of white noise and makes identical
// neighbours common, which a median-based noise scale (noise_estimate.h) reads in steps; so a step
// coarse against the channel's noise is reported (never excluded), a fine one is not.
#pragma once

#include <optional>

#include "diagnosis/data_quality.h"
#include "diagnosis/recorded_channels.h"

namespace gc {

/// The channel's step [unit]: the smallest gap between distinct values, or a half, third or
/// quarter of it, when at least 90 % of the gaps are whole multiples of it (within 2 % of a step)
/// and the channel has at most half as many distinct values as samples. nullopt otherwise.
std::optional<double> quantisation_step(const std::vector<double>& values);

/// A finding when the step is at least settings.coarse_step_share of the channel's noise sigma
/// (difference_sigma), with what rounding adds to the noise.
std::optional<DataQualityFinding> coarse_quantisation(const RecordedChannel& channel, const DataQualitySettings& settings);

}  // namespace gc
