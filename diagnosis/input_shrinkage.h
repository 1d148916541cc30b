// The inputs read back toward their own centred average: what a model fed noisy input sensors
// should have been fed. A torque transducer's or a proximity probe's noise e enters the model's
// prediction as dM/dx e, which the bridges never saw; the measured moments then look less
// sensitive to the inputs than the model (errors in the variables attenuate every slope), and any
// effect that lowers the model's sensitivity (a compliance, an offset of the misalignment) fits
// that attenuation with a real held-out gain and no physics. The Wiener estimate of an input
// whose truth moves slowly beside fast noise is its local mean plus a share of its departure from
// it:
//
//   x'(t) = m_W(t) + keep (x(t) - m_W(t)),   m_W(t) = the mean of x over [t - W/2, t + W/2],
//
// keep in [0, 1] (0: the local mean alone; 1: the input as recorded). Centred, so it smooths
// without shifting anything in time; per channel, because each sensor has its own noise.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "core/recorded_sample.h"

namespace gc {

struct InputShrink {
  double window_s = 0.0;  ///< W, the centred window [s]
  double keep = 1.0;      ///< the share of the departure from the window's mean kept, in [0, 1]
  bool none() const { return window_s <= 0.0 || keep >= 1.0; }
};

/// One shrink per input channel the paper's model reads.
struct InputShrinks {
  InputShrink torque;        ///< T
  InputShrink misalignment;  ///< zeta
  InputShrink direction;     ///< beta, averaged as a unit vector and kept along the shorter arc
  bool none() const { return torque.none() && misalignment.none() && direction.none(); }
};

/// `observations` with the inputs of `rows` (positions in time order; the windows run over them
/// only, so excluded rows neither feed nor receive an average) read back by `shrinks`. Derived
/// inputs (rates, loading and travel direction) are left as recorded: they are already averaged
/// over half a second. Rows not listed are copied unchanged.
std::vector<RecordedSample> with_shrunk_inputs(std::span<const RecordedSample> observations,
                                               std::span<const std::size_t> rows, const InputShrinks& shrinks);

}  // namespace gc
