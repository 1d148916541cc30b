// The experiment that would tell two effects apart when a recording cannot: sweep one recorded
// input at a time, beyond what the recording covered, and find where the two fitted models'
// predictions part by more than the noise; failing that, tilt the shaft (eq 48's gamma), which
// tells a weight from a channel offset.
#pragma once

#include <span>
#include <string>

#include "core/coupling_model.h"
#include "core/recorded_sample.h"

namespace gc {

struct SeparatingExperiment {
  std::string input;        ///< "torque", "misalignment", "direction", "loading_direction", "temperature", "speed", "tilt"; empty: none
  double value = 0.0;       ///< where the predictions part most [input unit]
  double difference_nm = 0.0;  ///< |prediction a - prediction b| there, relative to the reference
  std::string advice;       ///< one sentence for the user
};

/// Speed and temperature are swept too where every row records them.
/// `a` and `b` are the base model with either effect fitted; `rows` the recording's usable rows;
/// `noise_sigma_nm` the pooled noise. The sweeps run from a reference sample at the recording's
/// median torque and misalignment: torque 0.1 to 1.5 times the recorded maximum, misalignment 0
/// to 90 % of the jam angle, every direction, both loading directions.
SeparatingExperiment separating_experiment(const CouplingModel& a, const CouplingModel& b,
                                           std::span<const RecordedSample> observations,
                                           std::span<const std::size_t> rows, double noise_sigma_nm);

}  // namespace gc
