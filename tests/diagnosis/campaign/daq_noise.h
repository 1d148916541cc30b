// Noise of a real test-cell DAQ on the two bending channels, written for the campaign: heavy-tailed
// white noise (Student-t, 3 degrees of freedom), AR(1) coloured noise whose level wanders slowly,
// telemetry spikes, a slow bridge drift, and the export's own defects (ADC quantisation,
// duplicated time stamps, a few empty cells). Seeded SplitMix64 streams (independent/
// test_cell_noise.h), so every platform draws the same numbers.
#pragma once

#include <cstdint>
#include <vector>

#include "core/measurement_sample.h"

namespace gc::campaign {

struct NoiseSpec {
  double t3_scale_nm = 0.0;      ///< scale of the Student-t(3) white noise (std = sqrt(3) x scale)
  double ar_sigma_nm = 0.0;      ///< marginal sigma of the AR(1) noise at level factor 1
  double ar_tau_s = 1.5;         ///< its correlation time (phi = exp(-dt / tau))
  bool ar_level_wanders = false; ///< sigma x a slow log-normal factor in [0.5, 2] (tau 300 s)
  double spike_share = 0.0;      ///< share of samples (per channel) with a spike
  double spike_nm = 0.0;         ///< spike size (sign random, size x U(0.7, 1.3))
  double drift_nm = 0.0;         ///< std of the slow bridge drift (OU, tau 2000 s), per channel
  double lsb_nm = 0.0;           ///< ADC quantisation step of the moment channels (0: none)
  double duplicate_share = 0.0;  ///< share of rows whose time stamp repeats the previous one
  int empty_cells = 0;           ///< rows with one empty cell (malformed, the reader excludes them)
};

/// The noise the campaign's effect cases share: about 2.2 kN·m in all.
NoiseSpec standard_daq();

struct DaqNoise {
  std::vector<SensorMoments> moments;  ///< additive noise [N·m] (before quantisation)
  std::vector<bool> duplicate_time;    ///< row i carries row i-1's time stamp
  std::vector<int> empty_column;       ///< -1, or the column (0-based) left empty in row i
};

DaqNoise draw_noise(const NoiseSpec& spec, std::size_t rows, std::uint64_t seed);

/// Rounds to the ADC step (no-op for lsb <= 0).
double quantise(double value, double lsb);

}  // namespace gc::campaign
