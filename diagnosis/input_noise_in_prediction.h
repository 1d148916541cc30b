// The white noise the input sensors' noise puts in the model's prediction. A model fed a noisy
// misalignment predicts the probes' noise as moments the bridges never saw; a design made from the
// same measured inputs holds that noise too (errors in the variables), and wherever the moments'
// own noise no longer drowns it (prewhitened, prewhitening.h) a design of the inputs explains it.
#pragma once

#include <cstddef>
#include <span>

#include <Eigen/Dense>

#include "core/coupling_model.h"
#include "core/recorded_sample.h"

namespace gc {

/// Per moment channel [N·m]: for each input the model reads (torque, misalignment amplitude and
/// direction, speed and temperature where recorded), its sensor's noise (model_jumps.h's
/// input_noise_sigma on `rows`, in time order) times how far the prediction moves over one noise
/// deviation of it, half the central difference over +-1 deviation, its square's median over up to
/// 64 evenly spaced rows (a row beside a step of the teeth in contact moves by the step); summed
/// over the inputs in quadrature. 0 where the inputs carry no noise.
Eigen::Array2d input_noise_in_prediction(const CouplingModel& model, std::span<const RecordedSample> observations,
                                         std::span<const std::size_t> rows);

}  // namespace gc
