// When the moment channels see the inputs, with several effects in one model (core/input_timing.h):
// each effect's delay and averaging adds to the others', as lags in series do (a channel skewed by
// delay a, behind a filter that delays by b, sees the inputs a + b late). CouplingModel and a joint
// effect (joint_effect.h) both sum their effects' timings so.
#pragma once

#include <memory>
#include <span>

#include "core/effects/effect.h"
#include "core/input_timing.h"

namespace gc {

/// The sum of `effects`' input timings at `sample` [s].
InputTiming summed_input_timing(std::span<const std::shared_ptr<const Effect>> effects, const MeasurementSample& sample);

}  // namespace gc
