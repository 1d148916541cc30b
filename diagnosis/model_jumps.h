// Rows where the model jumps within the input sensors' noise. The paper's model counts whole teeth
// in each quarter of the coupling (int(q N / 4), eqs 13 and 42-43): where q crosses a step, two
// more teeth carry load and the moments jump (46 to 48 teeth, 2.1 kN·m, within 200 N·m of torque
// on the NREL downwind coupling at 0.71 deg). A torque held within a transducer's noise of such a
// step is logged on either side of it at random, and the model fed the logged torque jumps with it,
// where the coupling does not: a bias of a share of the jump over the whole hold (0.9 kN·m over the
// last third of a recording with 1.3 kN·m of torque noise, 0.1 % of its span). No average of the
// inputs takes it out, since it flips with noise of any size that reaches the step; and any effect
// that moves the moments by as much over the hold fits it, with a real held-out gain and no physics.
//
// Each row is tested where the model is: the prediction at the logged inputs and at two noise
// deviations either side in torque, and in misalignment, and the second difference between them.
// (Only holds leave a bias, where a ramp's crossings fall at random either side of the true one;
// but a staircase of one-second stairs holds too briefly for a running median to tell, and the
// claim that took its bias came back when only holds were left out.)
// A smooth model's curvature over so small a step is a fraction of a newton-metre; a jump is the
// jump itself. Rows whose second difference exceeds a quarter of the moments' noise are left out of
// the physics and reported, like spikes, as what they are.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

#include "core/coupling_model.h"
#include "core/recorded_sample.h"
#include "diagnosis/data_quality.h"
#include "diagnosis/parallel_for.h"

namespace gc {

/// At most this many rows, evenly spaced, are tested; the rows between two tested ones follow the
/// one before them.
inline constexpr std::size_t kJumpTestedRows = 20000;

/// The noise of an input sensor: 1.4826 times the median absolute departure of its readings from
/// their centred running median (input_shrinkage.h: a programme's steps and ramps pass a running
/// median; the noise does not), at up to kJumpTestedRows rows, the least over windows of 0.25, 1
/// and 4 s (at least 9 rows): the longest sees a transducer's filtered noise, the shortest is not
/// reached by a sweep that reverses every few seconds (over 4 s alone, a noise-free sweep of 10 s
/// read as 2 mrad of probe noise). `value` picks the input; rows in time order.
double input_noise_sigma(std::span<const RecordedSample> observations, const std::vector<std::size_t>& rows,
                         double (*value)(const MeasurementSample&));

/// The finding (DataQualityKind::model_jump) for the rows of `rows` (time order) where `model`
/// jumps within two deviations of the torque or misalignment sensor's noise by more than a quarter
/// of `moment_sigma_nm`, to be excluded. nullopt when there are none, when they would be more than
/// half the rows (the running median then saw a programme's wander, not a sensor's noise), or when
/// the inputs carry no noise.
std::optional<DataQualityFinding> rows_at_model_jumps(const CouplingModel& model,
                                                      std::span<const RecordedSample> observations,
                                                      const std::vector<std::size_t>& rows, double moment_sigma_nm,
                                                      const ParallelFor& parallel);

}  // namespace gc
