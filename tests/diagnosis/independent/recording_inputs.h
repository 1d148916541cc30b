// The inputs of a hidden-truth recording: one of the paper's load sequences (diagnosis/synthesis) for
// the upwind coupling at two directions, 1920 samples 0.1 s apart, with what a test cell also
// logs on every sample: shaft speed, its integral the rotation phase, and the oil temperature.
#pragma once

#include <vector>

#include "core/measurement_sample.h"
#include "diagnosis/synthesis/load_sequence.h"

namespace gc::independent {

/// Speed 12 +- 2 rpm on a 23 s period (the drive's speed control hunting, unrelated to the load
/// sequence); rotation phase its integral from zero [rad]; temperature rising 35 -> 55 deg C over
/// the run with a 1.5 deg C wobble on a 31 s period (the oil heating up under load). Loading
/// direction derived as the recording reader does (core/loading_direction.h).
std::vector<MeasurementSample> recording_inputs(LoadSequenceKind kind);

/// Direction of travel of the misalignment amplitude from the sequence itself: the sign of
/// zeta(i+1) - zeta(i-1) beyond 1e-6 rad, the last sign held through still stretches, 0 before the
/// first move. Independent of the library's loading-direction tracker.
std::vector<int> travel_direction(const std::vector<MeasurementSample>& samples);

}  // namespace gc::independent
