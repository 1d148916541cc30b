#include "core/effects/summed_input_timing.h"

namespace gc {

InputTiming summed_input_timing(std::span<const std::shared_ptr<const Effect>> effects, const MeasurementSample& sample) {
  InputTiming sum;
  for (const auto& effect : effects) {
    const InputTiming t = effect->input_timing(sample);
    sum.delay_s += t.delay_s;
    sum.average_s += t.average_s;
  }
  return sum;
}

}  // namespace gc
