// When the moment channels see the inputs. A DAQ that samples the bending bridges through another
// card or filter than the torque and misalignment channels records M(t - tau) beside T(t) and
// zeta(t) (a skew), and a demodulator that averages the rotating bridges over a revolution records
// the mean of M over it (a lag). Both are properties of the recording's time axis, not of one
// sample: a model with such an effect (moment_delay, docs/effects.md) predicts sample i of a
// recording from the recording's own inputs at t_i - delay_s, averaged over the average_s before
// that (core/coupling_model.h, predict_at). The model averages the inputs, not its moments: one
// evaluation a sample, and the same to first order where the moments are smooth in the inputs.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "core/measurement_sample.h"
#include "core/recorded_sample.h"

namespace gc {

struct InputTiming {
  double delay_s = 0.0;    ///< the moments are recorded this long after the inputs [s]
  double average_s = 0.0;  ///< and averaged over this long before that [s], >= 0
  bool none() const { return delay_s == 0.0 && average_s == 0.0; }
};

/// The inputs an averaging window sums, for samples [first, first + size) of a recording, as
/// columns: time, torque, misalignment and the direction as a unit vector (cos beta, sin beta),
/// computed once for many windows. An average over a demodulator's revolution at a few rpm spans
/// hundreds of samples, and each window took a sine and a cosine of every one (81 % of a 15,046-row
/// diagnosis with a moment delay). The window reads the same numbers and sums them in its order.
struct WindowColumns {
  std::size_t first = 0;
  std::vector<double> time_s, torque_nm, misalignment_rad, cos_beta, sin_beta;
  /// Samples [first, last] of `recording`.
  WindowColumns(std::span<const RecordedSample> recording, std::size_t first, std::size_t last);
  bool holds(std::size_t k) const { return k >= first && k - first < time_s.size(); }
};

/// Sample i of a sequence in time order (duplicated time stamps allowed), its inputs taken at
/// t_i - delay_s: interpolated linearly between the neighbouring samples (directions along the
/// shorter arc, the loading direction of the earlier neighbour), averaged over the samples of the
/// average_s before that time when average_s > 0 (directions as unit vectors); held at the first or
/// last sample beyond the sequence. Its time stays t_i, and `inputs_timed` is set.
/// `columns`: the window's samples where it holds them (the same numbers).
MeasurementSample timed_input(std::span<const MeasurementSample> sequence, std::size_t i, const InputTiming& timing);
MeasurementSample timed_input(std::span<const RecordedSample> recording, std::size_t i, const InputTiming& timing,
                              const WindowColumns* columns = nullptr);

}  // namespace gc
