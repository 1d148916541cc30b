#include "analysis/derived_inputs.h"

namespace gc::analysis {

void DerivedInputs::next(MeasurementSample& sample) {
  sample.loading_direction = loading_.next(sample.time_s, sample.misalignment_rad);
  sample.travel_direction = loading_.last_travel();
  sample.misalignment_rate_rad_s = misalignment_rate_.next(sample.time_s, sample.misalignment_rad);
  sample.torque_rate_nm_s = torque_rate_.next(sample.time_s, sample.torque_nm);
  // Every kept row of a recording with a speed column has a speed (an empty cell excludes the
  // row), so the trapezoid runs over the kept samples, across any excluded between them.
  if (sample.speed_rpm) sample.rotation_phase_rad = phase_.next(sample.time_s, *sample.speed_rpm);
}

}  // namespace gc::analysis
