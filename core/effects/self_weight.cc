// Self-weight of the coupling and shaft at the sensors, eq 48:
//   M_sy' = M_y' - s (W_c cos(gamma) L_s + w_sh cos(gamma) L_s^2 / 2),  M_sz' = M_z'.
#include "core/effects/registration.h"

namespace gc {
namespace {

const EffectInfo kInfo{
    "self_weight",
    "The weight of the hub and half the shaft bends the shaft between coupling and strain "
    "gauges: a constant moment about y' at the sensors.",
    "Section 4.3, eq 48",
    {{"weight_scale", "-", "s, the share of the coupling's weights (W_c, w_sh, L_s, gamma) that acts",
      0.0, 5.0, 0.0, 1.0, {0.5, 2.0}}}};

class SelfWeight final : public Effect {
 public:
  explicit SelfWeight(const ParameterValues& values)
      : Effect(kInfo, values), scale_(value("weight_scale")) {}

  void adjust_outputs(const MeasurementSample&, const ModelContext& context, const ModelState&,
                      SensorMoments& moments) const override {
    moments.y_nm -= scale_ * context.self_weight_moment_nm;
  }

 private:
  double scale_;
};

}  // namespace

EffectRegistration self_weight_effect() { return register_effect<SelfWeight>(kInfo); }

}  // namespace gc
