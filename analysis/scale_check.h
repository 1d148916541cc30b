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

/// Where the moments came from, for the fix a unit-slip error names.
enum class UnitFix {
  cli,      ///< a recording read by the CLI: rename the column or --columns; --force-scale
  python,   ///< a recording read by Python: rename the column or columns=; force_scale=True
  stream,   ///< a live stream (the monitor): the publisher must send N·m, as the topic says
};

/// The one wording of a unit slip (`refusal`, MomentScale::refusal) at `source`: a unit error,
/// the finding, and the fix for `fix`. validate, diagnose, replay, the monitor (and through its
/// health the dashboard and `status`) and Python all say it with this function.
std::string unit_slip_error(std::string_view source, std::string_view refusal, UnitFix fix);

/// Throws gc::InvalidInput naming "recording" when `refusal` holds one, worded by
/// unit_slip_error.
void refuse_unit_slip(std::string_view source, const std::optional<std::string>& refusal,
                      UnitFix fix = UnitFix::cli);

/// Degrees under a _rad header make the misalignment 57.3 times too large; radians under _deg,
/// 57.3 times too small. A warning when the largest misalignment of the recording, times or
/// divided by 57.3, would fall between 0.1 and 3 jam angles while as read it is far outside.
std::optional<std::string> misalignment_scale_warning(double largest_misalignment_rad,
                                                      double jam_angle_rad);

/// kN·m under a torque_nm header make the torque 1000 times too small: the model then refuses
/// light torques near the jam angle with a reason about eq 22, not the unit (issue 39). A
/// warning when the largest torque, times 1000, would fall between 0.1 and 3 T_ref while as read
/// it is under a hundredth of it.
std::optional<std::string> torque_scale_warning(double largest_torque_nm, double reference_torque_nm);

}  // namespace gc::analysis
