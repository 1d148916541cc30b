// Worked example of docs/adding-an-effect.md: friction that changes with the oil temperature.
// Section 6.3: "Future experiments will investigate the effects of temperature on friction
// coefficients." Adds to eq 37's mu:
//   mu += dmu_dT (T_oil - T_ref)
// It is compiled and tested here (tests/core/example_effect_test.cc) but not registered in the
// library, so the diagnosis tests can treat it as a mechanism the library does not have.
#include "core/effects/registration.h"
#include "core/model_error.h"

namespace gc {
namespace {

// 1. Describe the physics and the parameters: name, SI unit, meaning, bounds, neutral value
//    (where the effect does nothing), default, and the plausible range (where a fitted value can
//    still be called this physics; {} for the whole of the bounds), and the measured inputs
//    without which it changes nothing.
const EffectInfo kInfo{
    "temperature_friction",
    "Tooth friction that falls as the oil warms and thins (or rises as it cools).",
    "Section 6.3 (future work named by the paper)",
    {{"dmu_dT_per_k", "1/K", "change of mu per kelvin of oil temperature", -0.01, 0.01, 0.0, -0.001,
      {-0.005, 0.0}},
     {"reference_temperature_c", "deg C", "T_ref, where the effect adds nothing", -40.0, 150.0,
      40.0, 40.0, {}}},
    {OptionalInput::temperature}};

// 2. One class: read the parameters once, in the constructor; adjust in a const method.
class TemperatureFriction final : public Effect {
 public:
  explicit TemperatureFriction(const ParameterValues& values)
      : Effect(kInfo, values),
        slope_(value("dmu_dT_per_k")),
        reference_(value("reference_temperature_c")) {}

  void adjust_inputs(const MeasurementSample& sample, const ModelContext&,
                     ModelState& state) const override {
    if (slope_ == 0.0) return;  // neutral: needs no temperature channel
    if (!sample.temperature_c) {
      throw InvalidInput("sample.temperature_c", "required by effect " + name() +
                                                     ": record a temperature_c column");
    }
    state.point.friction_coefficient += slope_ * (*sample.temperature_c - reference_);
  }

 private:
  double slope_;
  double reference_;
};

}  // namespace

// 3. The registration function; in the library, one line in core/effects/effect_registry.cc
//    declares it and lists it in effect_registry().
EffectRegistration temperature_friction_effect() {
  return register_effect<TemperatureFriction>(kInfo);
}

}  // namespace gc
