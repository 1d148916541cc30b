// A continuous 10 Hz test programme of the upwind coupling's test cell, written for the campaign
// (no library code): a torque staircase, misalignment sweeps up and down at two directions and two
// speeds, a field-like stochastic torque block and a 3-15-3 rpm speed run. These are the TRUE
// inputs; what the DAQ logs may differ (a sensor effect), and the moments come from cases.h.
#pragma once

#include <cstdint>
#include <vector>

namespace gc::campaign {

/// One sample of the true operating state.
struct InputRow {
  double time_s = 0.0;
  double torque_nm = 0.0;
  double zeta_rad = 0.0;      ///< commanded misalignment amplitude
  double beta_rad = 0.0;      ///< commanded misalignment direction
  double speed_rpm = 0.0;
  double temperature_c = 0.0; ///< oil temperature
  double phase_rad = 0.0;     ///< shaft angle since the recording started (the DAQ triggers on the keyphasor)
};

struct ProgrammeOptions {
  std::uint64_t seed = 1;          ///< the stochastic torque block and the wandering misalignment
  std::size_t rows = 14150;        ///< the programme repeats (new random blocks) until this many rows
  double start_time_s = 0.0;       ///< DAQ clock at the first row (a continuation run starts later)
  double start_temperature_c = 35.0;
  double zeta_max_deg = 0.45;      ///< top of the sweeps (cases with a large rig offset lower it)
};

constexpr double kSampleRateHz = 10.0;
constexpr double kDt = 1.0 / kSampleRateHz;

std::vector<InputRow> test_programme(const ProgrammeOptions& options);

/// Length of one pass of the programme [rows].
std::size_t programme_pass_rows();

}  // namespace gc::campaign
