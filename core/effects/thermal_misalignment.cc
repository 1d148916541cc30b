// A misalignment that grows with temperature: the gearbox housing and its supports expand as the
// oil warms through a test, and the shafts they carry move against the drivetrain under test
// (the thermal-growth allowance of a coupling alignment). The displacement sensors measure the
// coupling's angle where they sit; a housing that tilts or rises elsewhere adds a misalignment
// they do not see, in proportion to the temperature rise (linear thermal expansion):
//   added vector = g (theta - theta_0) along beta_t,
// with theta the oil temperature. Below theta_0 the vector points the other way. Samples without
// a temperature are left alone.
#include "core/effects/registration.h"

namespace gc {
namespace {

const EffectInfo kInfo{
    "thermal_misalignment",
    "A misalignment from thermal growth of the gearbox housing: g (theta - theta_0) along a "
    "direction beta_t, added to the measured misalignment vector, with theta the oil temperature.",
    "Section 6.3.1 (misalignment the sensors do not see), thermal growth",
    {{"growth_rad_per_c", "rad/degC", "g, the misalignment added per deg C of oil temperature", -2e-3, 2e-3, 0.0,
      0.0, {-2e-4, 2e-4}, false, 0.0, "the gearbox supports' thermal growth (a housing that rises as it warms)"},
     {"reference_temperature_c", "degC", "theta_0, the temperature at which the rig was aligned", -40.0, 150.0,
      40.0, 40.0, {0.0, 80.0}, false, 0.0, "the temperature of the alignment", true},
     {"direction_rad", "rad", "beta_t, the direction of the growth, as beta", -2.0 * M_PI, 2.0 * M_PI, 0.0, 0.0,
      {-M_PI, M_PI}, false, 2.0 * M_PI}},
    {OptionalInput::temperature}};

class ThermalMisalignment final : public Effect {
 public:
  explicit ThermalMisalignment(const ParameterValues& values)
      : Effect(kInfo, values),
        g_(value("growth_rad_per_c")),
        theta0_(value("reference_temperature_c")),
        beta_t_(value("direction_rad")) {}

  void adjust_inputs(const MeasurementSample& sample, const ModelContext&, ModelState& state) const override {
    if (!sample.temperature_c) return;
    add_misalignment(g_ * (*sample.temperature_c - theta0_), beta_t_, state.point);
  }

 private:
  double g_, theta0_, beta_t_;
};

}  // namespace

EffectRegistration thermal_misalignment_effect() { return register_effect<ThermalMisalignment>(kInfo); }

}  // namespace gc
