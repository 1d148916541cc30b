#include "live/measurement_wire.h"

#include <string>

#include "core/model_error.h"
#include "core/rotation_phase.h"

namespace gc::live {
namespace {

constexpr double kZeroCelsiusK = 273.15;

double finite(const char* member, double value) {
  require_finite(std::string("measurement.") + member, value);
  return value;
}

std::optional<double> optional_finite(const char* member, const double* value) {
  if (value == nullptr) return std::nullopt;
  return finite(member, *value);
}

}  // namespace

RecordedSample from_wire(const gearcoupling_Measurement& m) {
  RecordedSample s;
  s.input.time_s = finite("time_s", m.time_s);
  s.input.torque_nm = finite("torque_nm", m.torque_nm);
  s.input.misalignment_rad = finite("misalignment_rad", m.misalignment_rad);
  s.input.direction_rad = finite("direction_rad", m.direction_rad);
  s.measured = {finite("msy_nm", m.msy_nm), finite("msz_nm", m.msz_nm)};
  if (auto speed = optional_finite("speed_rad_s", m.speed_rad_s)) {
    s.input.speed_rpm = *speed / kRadPerSecondPerRpm;
  }
  if (auto temperature = optional_finite("temperature_k", m.temperature_k)) {
    s.input.temperature_c = *temperature - kZeroCelsiusK;
  }
  s.input.applied_moment_y_nm = optional_finite("applied_my_nm", m.applied_my_nm);
  s.input.applied_moment_z_nm = optional_finite("applied_mz_nm", m.applied_mz_nm);
  s.hub_motion_m = optional_finite("hub_motion_m", m.hub_motion_m);
  return s;
}

gearcoupling_Measurement to_wire(const RecordedSample& s, unsigned long long sequence_number,
                                 MeasurementOptionals& o) {
  gearcoupling_Measurement m{};
  m.sequence_number = sequence_number;
  m.time_s = s.input.time_s;
  m.torque_nm = s.input.torque_nm;
  m.misalignment_rad = s.input.misalignment_rad;
  m.direction_rad = s.input.direction_rad;
  m.msy_nm = s.measured.y_nm;
  m.msz_nm = s.measured.z_nm;
  const auto point = [](const std::optional<double>& value, double& slot, double scale,
                        double offset) -> double* {
    if (!value) return nullptr;
    slot = *value * scale + offset;
    return &slot;
  };
  m.speed_rad_s = point(s.input.speed_rpm, o.speed_rad_s, kRadPerSecondPerRpm, 0.0);
  m.temperature_k = point(s.input.temperature_c, o.temperature_k, 1.0, kZeroCelsiusK);
  m.applied_my_nm = point(s.input.applied_moment_y_nm, o.applied_my_nm, 1.0, 0.0);
  m.applied_mz_nm = point(s.input.applied_moment_z_nm, o.applied_mz_nm, 1.0, 0.0);
  m.hub_motion_m = point(s.hub_motion_m, o.hub_motion_m, 1.0, 0.0);
  return m;
}

}  // namespace gc::live
