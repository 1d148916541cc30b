#include "core/rotation_phase.h"

#include <algorithm>

namespace gc {

double RotationPhaseIntegrator::next(double time_s, double speed_rpm) {
  const double speed_rad_s = speed_rpm * kRadPerSecondPerRpm;
  if (started_) {
    phase_rad_ += (time_s - time_s_) * 0.5 * (speed_rad_s_ + speed_rad_s);  // trapezoid
  }
  started_ = true;
  time_s_ = time_s;
  speed_rad_s_ = speed_rad_s;
  return phase_rad_;
}

bool derive_rotation_phase(std::span<MeasurementSample> samples) {
  const bool every_speed = std::all_of(samples.begin(), samples.end(),
                                       [](const MeasurementSample& s) { return s.speed_rpm.has_value(); });
  if (!every_speed) return false;
  RotationPhaseIntegrator phase;
  for (MeasurementSample& s : samples) s.rotation_phase_rad = phase.next(s.time_s, *s.speed_rpm);
  return true;
}

}  // namespace gc
