// The pressure-angle rotation of the moment direction, eqs 44-45: the most loaded tooth, and
// with it the z'' axis, sits phi from the misalignment axis, so the moments turn by s * phi.
#include "core/coupling_geometry.h"
#include "core/effects/registration.h"

namespace gc {
namespace {

const EffectInfo kInfo{
    "pressure_angle_rotation",
    "With a large pressure angle the most loaded tooth does not sit on the misalignment axis "
    "but phi from it; the induced moments turn with it (Figure 3b).",
    "Section 4.1 (after eq 19), eqs 44-47",
    {{"shift_scale", "-", "s, the share of the pressure angle phi the moment direction turns by",
      0.0, 2.0, 0.0, 1.0, {0.0, 1.5}}}};

class PressureAngleRotation final : public Effect {
 public:
  explicit PressureAngleRotation(const ParameterValues& values)
      : Effect(kInfo, values), scale_(value("shift_scale")) {}

  void adjust_inputs(const MeasurementSample&, const ModelContext& context,
                     ModelState& state) const override {
    state.frame_shift_rad += scale_ * context.geometry.pressure_angle_rad();
  }

 private:
  double scale_;
};

}  // namespace

EffectRegistration pressure_angle_rotation_effect() {
  return register_effect<PressureAngleRotation>(kInfo);
}

}  // namespace gc
