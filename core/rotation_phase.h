// Shaft rotation angle as a derived input (MeasurementSample::rotation_phase_rad): integrated
// from the recorded speed over time, so that effects that depend on where the shaft is in its
// turn (e.g. eccentricity, spacing errors) need no per-call state.
#pragma once

#include <numbers>
#include <span>

#include "core/measurement_sample.h"

namespace gc {

/// One rpm in rad/s: a turn, 2 pi rad, per 60 s.
inline constexpr double kRadPerSecondPerRpm = 2.0 * std::numbers::pi / 60.0;

/// Integrates speed over time sample by sample, by the trapezoidal rule:
/// phi_i = phi_{i-1} + (t_i - t_{i-1}) (omega_{i-1} + omega_i) / 2, omega = 2 pi n / 60 [rad/s],
/// phi_0 = 0. The angle is not wrapped: it counts whole turns too [rad]. A value type: one per
/// recording, fed in time order.
class RotationPhaseIntegrator {
 public:
  /// The phase at this sample [rad], from its time [s] and speed [rpm].
  double next(double time_s, double speed_rpm);

 private:
  bool started_ = false;
  double time_s_ = 0.0;
  double speed_rad_s_ = 0.0;
  double phase_rad_ = 0.0;
};

/// Sets rotation_phase_rad on every sample of a recording in time order, when every sample has
/// a speed; otherwise leaves every sample as it is (a phase cannot be integrated across a gap).
/// Returns whether it set them.
bool derive_rotation_phase(std::span<MeasurementSample> samples);

}  // namespace gc
