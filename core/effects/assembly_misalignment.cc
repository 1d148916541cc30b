// An initial misalignment from assembly tolerances and structural deflection, added as a
// vector to the measured one (Section 6.3.1: "misalignment of 17 % at zero applied moment
// suggested an initial misalignment caused by assembly tolerances").
#include <cmath>

#include "core/effects/registration.h"

namespace gc {
namespace {

const EffectInfo kInfo{
    "assembly_misalignment",
    "A misalignment the sensors do not see (assembly tolerances, structural deflection), "
    "added to the measured misalignment vector.",
    "Section 6.3.1",
    {{"zeta0_rad", "rad", "amplitude of the initial misalignment", 0.0, 0.05, 0.0, 0.0, {0.0, 0.3, RangeScale::jam_angle},
      false, 0.0, "the alignment of the rig (a poor alignment, a settled foundation, a worn bearing)"},
     // Profiled: the cost has valleys in the direction too (the steps of eqs 42-43), and a small
     // offset's descent from its probes ended in another one (docs/effects.md).
     {"beta0_rad", "rad", "its direction, as beta", -2.0 * M_PI, 2.0 * M_PI, 0.0, 0.0, {-M_PI, M_PI}, false,
      2.0 * M_PI, {}, true}}};

class AssemblyMisalignment final : public Effect {
 public:
  explicit AssemblyMisalignment(const ParameterValues& values)
      : Effect(kInfo, values), zeta0_(value("zeta0_rad")), beta0_(value("beta0_rad")) {}

  void adjust_inputs(const MeasurementSample&, const ModelContext&,
                     ModelState& state) const override {
    add_misalignment(zeta0_, beta0_, state.point);
  }

 private:
  double zeta0_, beta0_;
};

}  // namespace

EffectRegistration assembly_misalignment_effect() {
  return register_effect<AssemblyMisalignment>(kInfo);
}

}  // namespace gc
