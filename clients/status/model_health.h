// A test cell's model health at a glance: the dashboard's badge beside "alive" and the "model"
// column of `gearcoupling status`, from the monitor's health (per channel M_sy', M_sz': the
// systematic part of the RMSE against the noise level). The thresholds are defined here and
// only here (docs/dashboard.md, "Model health").
#pragma once

#include <cstdint>
#include <string_view>

#include "diagnosis/validation/worst_regions.h"
#include "idl/live_status.pb.h"

namespace gc::status {

/// A channel whose systematic part s is at least this many times its noise n is far off: the
/// model's part of the mean-square error, s^2 / (s^2 + n^2), is 90 % or more (the RMSE at least
/// 3.16 x the noise). Mirrors kAtNoiseLevelShare (1/3: at most 10 %).
inline constexpr double kFarOffRatio = 3.0;

enum class ModelHealth {
  unknown,         ///< no health yet, or fewer than 2 samples in the window (grey)
  at_noise_level,  ///< both channels: s < kAtNoiseLevelShare x n, or s = 0 (green)
  systematic,      ///< a channel between the two (amber)
  far_off,         ///< a channel with s >= kFarOffRatio x n, or s > 0 with n = 0 (red)
  /// The moments are a thousand times off (kN·m under an _nm header, the monitor's unit check):
  /// no model's health can be read from them (red, "unit error"; issue 39).
  unit_error,
};

/// One channel's health from its systematic part and noise [N·m] (non-negative).
ModelHealth channel_health(double systematic_nm, double noise_nm);

/// The worse of the two channels of `model`; unknown below 2 samples in the window.
ModelHealth model_health(const ::gearcoupling::v1::ModelPeriodRecord& model,
                         std::uint64_t window_samples);

/// The badge with hysteresis (issue 39: it flipped between red and amber every second during a
/// steady fault whose ratio sat near 3): a cell leaves `previous` only once a channel is clearly
/// past the threshold: far off until below kHysteresis x kFarOffRatio, at the noise level until
/// kAtNoiseLevelShare / kHysteresis or more. Entering a level takes the plain thresholds.
inline constexpr double kHysteresis = 0.8;
ModelHealth model_health(const ::gearcoupling::v1::ModelPeriodRecord& model,
                         std::uint64_t window_samples, ModelHealth previous);

/// "unknown", "at_noise_level", "systematic", "far_off", "unit_error": TestCellRecord.model_health.
std::string_view to_string(ModelHealth health);
/// The inverse of to_string; unknown for any other text.
ModelHealth model_health_from(std::string_view text);

}  // namespace gc::status
