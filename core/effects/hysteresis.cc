// Test-bench hysteresis (Section 6.3: downwind data "scattered at large misalignment angles,
// which was caused by system hysteresis of the test bench"): the coupling's misalignment lags
// the measured one by a fixed angle against the direction of travel,
//   zeta_effective = max(0, zeta - d * lag),  d = +1 after a rise, -1 after a fall, 0 before any.
// d is the last travel (MeasurementSample::travel_direction), held through a hold: the friction
// that makes the lag keeps the coupling where it stuck when the misalignment stops, until the
// next move. (Read with the still-or-moving loading_direction, the lag vanished 0.5 s into every
// hold. The hidden hysteresis of the noise zoo and of the independent truths, and the campaigns'
// rig friction, each written from the physics by another hand, all hold it.)
#include <algorithm>

#include "core/effects/registration.h"

namespace gc {
namespace {

const EffectInfo kInfo{
    "hysteresis",
    "Friction and compliance in the load-application device make the coupling lag the "
    "measured misalignment: lower while and after it rises, higher while and after it falls "
    "(the friction holds the lag through a hold).",
    "Section 6.3",
    {{"lag_rad", "rad", "lag of the coupling behind the measured misalignment", 0.0, 0.01, 0.0,
      1e-4, {0.0, 0.1, RangeScale::jam_angle}}}};

class Hysteresis final : public Effect {
 public:
  explicit Hysteresis(const ParameterValues& values)
      : Effect(kInfo, values), lag_(value("lag_rad")) {}

  void adjust_inputs(const MeasurementSample& sample, const ModelContext&,
                     ModelState& state) const override {
    state.point.misalignment_rad =
        std::max(0.0, state.point.misalignment_rad - sample.travel_direction * lag_);
  }

 private:
  double lag_;
};

}  // namespace

EffectRegistration hysteresis_effect() { return register_effect<Hysteresis>(kInfo); }

}  // namespace gc
