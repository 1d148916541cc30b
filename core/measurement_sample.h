// One sample of a test-cell recording, as the model reads it (docs/recordings.md).
#pragma once

#include <optional>

namespace gc {

/// What was measured at one instant. SI units; angles in radians.
struct MeasurementSample {
  double time_s = 0.0;             ///< [s]
  double torque_nm = 0.0;          ///< T [N·m]
  double misalignment_rad = 0.0;   ///< zeta, measured amplitude [rad]
  double direction_rad = 0.0;      ///< beta, measured direction [rad]
  /// +1 while the misalignment amplitude rises, -1 while it falls, 0 when unknown or still.
  /// Derived from the sequence by the recording reader, so effects need no per-call state.
  int loading_direction = 0;
  /// The last direction of travel, +1 or -1, held through still stretches (0 before the first
  /// move): the side the spline's friction stays locked on after a move. Derived with
  /// loading_direction.
  int travel_direction = 0;
  std::optional<double> speed_rpm;            ///< [rpm]
  std::optional<double> temperature_c;        ///< [deg C]
  /// Shaft rotation angle, integrated from speed over time by whoever reads the recording
  /// (core/rotation_phase.h), so effects need no per-call state; where speed is recorded [rad].
  std::optional<double> rotation_phase_rad;
  /// dzeta/dt and dT/dt over the last half second, derived from the sequence by whoever reads
  /// the recording (core/input_rate.h); absent for the first samples [rad/s], [N·m/s].
  std::optional<double> misalignment_rate_rad_s;
  std::optional<double> torque_rate_nm_s;
  std::optional<double> applied_moment_y_nm;  ///< LAD moment about y [N·m]
  std::optional<double> applied_moment_z_nm;  ///< LAD moment about z [N·m]
  /// Set when the inputs were taken at the time the moment channels see them, from the recording
  /// (core/input_timing.h): an effect that lags the moments then has nothing left to do.
  bool inputs_timed = false;
};

/// The bending moments at the sensors, measured or predicted.
struct SensorMoments {
  double y_nm = 0.0;  ///< M_sy' [N·m]
  double z_nm = 0.0;  ///< M_sz' [N·m]
};

}  // namespace gc
