// Sliding friction whose coefficient depends on torque and misalignment (Sections 3 and 6.3:
// "The friction coefficient ... increases with the torque decrease or the misalignment
// increase"). It sets the mu of eq 37:
//   mu = mu0 + mu_low_torque * T_ref / T + mu_misalignment * zeta / xi
// with xi the jam angle (eqs 23-35).
#include "core/coupling_geometry.h"
#include "core/effects/registration.h"

namespace gc {
namespace {

const EffectInfo kInfo{
    "friction",
    "Coulomb friction of the axially sliding teeth (eqs 36-37), with a coefficient that rises "
    "at low torque and at large misalignment, as the paper's measured friction does.",
    "Sections 3 (eqs 1-4), 4.3 (eq 37), 6.3",
    {{"mu0", "-", "friction coefficient at the reference torque and no misalignment", 0.0, 0.5,
      0.0, 0.1, {0.02, 0.3}},
     {"mu_low_torque", "-", "rise of mu with T_ref / T", 0.0, 0.5, 0.0, 0.0, {0.0, 0.15}},
     {"reference_torque_nm", "N·m", "T_ref", 1e4, 1e8, 1.5e6, 1.5e6, {}},
     {"mu_misalignment", "-", "rise of mu from no misalignment to the jam angle", 0.0, 0.5, 0.0,
      0.0, {0.0, 0.3}}}};

class Friction final : public Effect {
 public:
  explicit Friction(const ParameterValues& values)
      : Effect(kInfo, values),
        mu0_(value("mu0")),
        mu_low_torque_(value("mu_low_torque")),
        reference_torque_nm_(value("reference_torque_nm")),
        mu_misalignment_(value("mu_misalignment")) {}

  void adjust_inputs(const MeasurementSample&, const ModelContext& context,
                     ModelState& state) const override {
    const double jam = context.geometry.jam_angle().angle_rad;
    state.point.friction_coefficient +=
        mu0_ + mu_low_torque_ * reference_torque_nm_ / state.point.torque_nm +
        mu_misalignment_ * state.point.misalignment_rad / jam;
  }

 private:
  double mu0_, mu_low_torque_, reference_torque_nm_, mu_misalignment_;
};

}  // namespace

EffectRegistration friction_effect() { return register_effect<Friction>(kInfo); }

}  // namespace gc
