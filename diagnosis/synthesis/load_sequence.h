// Load sequences of the paper's test-cell campaign (Section 6.3), as the inputs of synthetic
// recordings: applied-moment sweeps at fixed torque (Figures 10-11), torque sweeps at fixed
// misalignment (Figures 12-13) and the stepped torque ramp (Figure 14).
#pragma once

#include <optional>
#include <string_view>
#include <vector>

#include "core/measurement_sample.h"

namespace gc {

enum class LoadSequenceKind {
  moment_sweep,  ///< misalignment 0 -> +peak -> -peak -> 0 of the jam angle at fixed torques
  torque_sweep,  ///< torque up and down between two fractions of T_ref at +-30 %, +-60 % of xi
  torque_ramp,   ///< torque in equal steps from a first to a last value at fixed misalignment
};

/// "moment-sweep", "torque-sweep", "torque-ramp"; empty for anything else.
std::optional<LoadSequenceKind> load_sequence_kind(std::string_view name);
std::string_view to_string(LoadSequenceKind kind);

struct LoadSequenceOptions {
  LoadSequenceKind kind = LoadSequenceKind::moment_sweep;
  int samples = 2000;                 ///< samples in the whole sequence, >= 2
  double jam_angle_rad = 0.0;         ///< xi of the coupling the sequence is for (eq 35)
  double reference_torque_nm = 1.5e6; ///< T_ref the fractions refer to
  double sample_period_s = 0.01;      ///< time between samples
  double direction_rad = 0.0;         ///< beta of positive misalignment; negative is beta + pi
  /// moment_sweep: one sweep at each torque, as fractions of T_ref (Figures 10-11).
  std::vector<double> sweep_torque_fractions = {0.2, 0.5, 1.0};
  double sweep_peak_fraction = 0.6;   ///< moment_sweep: peak misalignment / xi
  /// torque_sweep: torque from/to fraction of T_ref, one up-and-down per misalignment
  /// (Figures 12-13: 10 % to 95 % at +-30 % and +-60 % of xi).
  double sweep_low_fraction = 0.10;
  double sweep_high_fraction = 0.95;
  std::vector<double> sweep_misalignment_fractions = {0.3, -0.3, 0.6, -0.6};
  /// torque_ramp (Figure 14): steps from first to last torque at a fixed misalignment.
  double ramp_first_torque_nm = 0.1e6;
  double ramp_last_torque_nm = 2.2e6;
  int ramp_steps = 17;
  double ramp_misalignment_fraction = 0.3;
};

/// The input samples of one sequence, time from zero, loading_direction left 0 (the recording
/// reader derives it, core/loading_direction.h). Throws InvalidInput naming the option.
std::vector<MeasurementSample> load_sequence(const LoadSequenceOptions& options);

/// The sample at signed misalignment `fraction` of the jam angle: amplitude |fraction| xi,
/// direction beta for positive and beta + pi for negative (the paper's Figures 10-13 axes).
void set_signed_misalignment(double fraction, const LoadSequenceOptions& options,
                             MeasurementSample& sample);

}  // namespace gc
