// Silent unit errors in a recording's header: N·m values under a _knm header gave an RMSE of
// 109,936 kN·m and an R² of -23.8 with no hint why; radians under _deg passed unflagged. The
// values are finite and plausible one by one: only their scale against the model's gives
// them away. A warning, not an error: a model can be that wrong, and a test can run at a
// misalignment that small.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/measurement_sample.h"
#include "core/recorded_sample.h"

namespace gc::analysis {

/// The factor among 10, 100, 1000 and 57.3 (degrees per radian) nearest to `ratio` or to its
/// inverse, when within a factor of 1.5 of it; nothing otherwise (ratio near 1, or between).
std::optional<double> unit_slip_factor(double ratio);

/// The RMS of each moment channel, measured and predicted, over the samples a model compared.
class MomentScale {
 public:
  void add(const SensorMoments& measured, const SensorMoments& predicted);
  /// One warning per channel whose measured RMS is off from the model's by a unit-slip factor.
  /// A channel the model holds near zero (under a tenth of the other's RMS) is not judged.
  std::vector<std::string> warnings(std::string_view model_name) const;
  /// The warning of the first channel off by about 1000 (kN·m under a _nm header, N·m under
  /// _knm): a validation or a fit on such data prints nonsense (an R² of -3e7, a gain at its
  /// bound), so validate and diagnose refuse it (refuse_unit_slip) unless forced. nullopt when
  /// no channel is; 10, 100 and 57.3 stay warnings (a model can be that wrong).
  std::optional<std::string> refusal(std::string_view model_name) const;

 private:
  struct ChannelSlip {
    double factor;
    std::string warning;
  };
  std::vector<ChannelSlip> slips(std::string_view model_name) const;

  double measured_y_ = 0.0, measured_z_ = 0.0;   // sums of squares [N²·m²]
  double model_y_ = 0.0, model_z_ = 0.0;
  std::size_t count_ = 0;
};

/// Throws gc::InvalidInput naming "recording" when `refusal` holds one: `source`, the warning,
/// and what to do (fix the header or --columns; --force-scale runs anyway).
void refuse_unit_slip(std::string_view source, const std::optional<std::string>& refusal);

/// Degrees under a _rad header make the misalignment 57.3 times too large; radians under _deg,
/// 57.3 times too small. A warning when the largest misalignment of the recording, times or
/// divided by 57.3, would fall between 0.1 and 3 jam angles while as read it is far outside.
std::optional<std::string> misalignment_scale_warning(double largest_misalignment_rad,
                                                      double jam_angle_rad);

}  // namespace gc::analysis
