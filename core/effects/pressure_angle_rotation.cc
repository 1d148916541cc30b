// The pressure-angle rotation of the moment direction, eqs 44-45: the most loaded tooth, and
// with it the z'' axis, sits phi from the misalignment axis, so the moments turn by s * phi.
// The paper takes the shift as fixed. A rig's may grow with torque, as the load spreads from the
// few teeth on the misalignment axis to the flanks phi from it: s phi T / (T + T_s), which is the
// paper's s phi for T_s = 0 (the default) and at torques far above T_s.
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
      0.0, 2.0, 0.0, 1.0, {0.0, 1.5}},
     {"saturation_torque_nm", "N·m", "T_s: the shift grows as T / (T + T_s); 0: fixed (the paper)", 0.0, 1e7,
      0.0, 0.0, {0.0, 1.5e6}}}};

class PressureAngleRotation final : public Effect {
 public:
  explicit PressureAngleRotation(const ParameterValues& values)
      : Effect(kInfo, values), scale_(value("shift_scale")), saturation_(value("saturation_torque_nm")) {}

  void adjust_inputs(const MeasurementSample&, const ModelContext& context,
                     ModelState& state) const override {
    const double shift = scale_ * context.geometry.pressure_angle_rad();
    const double torque = state.point.torque_nm;
    // T_s = 0 keeps the paper's fixed shift bit for bit.
    state.frame_shift_rad += saturation_ > 0.0 ? shift * torque / (torque + saturation_) : shift;
  }

 private:
  double scale_, saturation_;
};

}  // namespace

EffectRegistration pressure_angle_rotation_effect() {
  return register_effect<PressureAngleRotation>(kInfo);
}

}  // namespace gc
