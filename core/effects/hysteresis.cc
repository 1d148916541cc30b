// Test-bench hysteresis (Section 6.3: downwind data "scattered at large misalignment angles,
// which was caused by system hysteresis of the test bench"): the coupling's misalignment lags
// the measured one by a fixed angle in the direction of loading,
//   zeta_effective = max(0, zeta - d * lag),  d = +1 rising, -1 falling, 0 unknown.
#include <algorithm>

#include "core/effects/registration.h"

namespace gc {
namespace {

const EffectInfo kInfo{
    "hysteresis",
    "Friction and compliance in the load-application device make the coupling lag the "
    "measured misalignment: lower while the misalignment rises, higher while it falls.",
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
        std::max(0.0, state.point.misalignment_rad - sample.loading_direction * lag_);
  }

 private:
  double lag_;
};

}  // namespace

EffectRegistration hysteresis_effect() { return register_effect<Hysteresis>(kInfo); }

}  // namespace gc
