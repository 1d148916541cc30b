// Test recordings for the diagnosis, generated in-process: the paper's load sequences (applied-
// misalignment sweeps at fixed torque, Figures 10-11; torque sweeps at fixed misalignment,
// Figures 12-13) through a CouplingModel plus seeded Gaussian noise.
#pragma once

#include <cstdint>
#include <vector>

#include "core/coupling_model.h"
#include "core/diagnosis/observation.h"

namespace gc::testing {

/// For each torque and direction, the misalignment rises 0 -> max and falls back, `points` samples
/// per ramp, loading direction +1 then -1; 1 s between samples.
std::vector<MeasurementSample> misalignment_sweeps(const std::vector<double>& torques_nm,
                                                   const std::vector<double>& directions_rad,
                                                   double max_misalignment_rad, int points);

/// For each misalignment and direction, the torque rises low -> high and falls back.
std::vector<MeasurementSample> torque_sweeps(const std::vector<double>& misalignments_rad,
                                             const std::vector<double>& directions_rad, double low_nm,
                                             double high_nm, int points);

/// Appends `b` to `a`, continuing its time.
std::vector<MeasurementSample> concatenated(std::vector<MeasurementSample> a, const std::vector<MeasurementSample>& b);

/// Measured moments: `truth`'s prediction plus N(0, sigma^2) per channel, seeded.
std::vector<Observation> synthesize(const CouplingModel& truth, const std::vector<MeasurementSample>& samples,
                                    double noise_sigma_nm, std::uint64_t seed);

}  // namespace gc::testing
