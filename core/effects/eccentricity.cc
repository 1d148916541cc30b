// Hub-sleeve eccentricity below the restoring torque (Sections 4.4 and 6.4): at low torque the
// hub rests on the sleeve under its weight, an initial misalignment of 0.04-0.08 deg that the
// torque removes as it approaches the restoring torque T_m of eqs 49-53:
//   zeta_e (1 - (T / (s T_m))^k) for T < s T_m, added in the direction of gravity.
// k = 1 (the default) fades linearly; k > 1 holds the sag until near s T_m and then lets go, as a
// hub that lifts off at once. Not below 1: a sag that drops at the first torque and lingers to
// s T_m has no mechanism, and on a stepped torque ramp it would trade against zeta_e.
#include <cmath>

#include "core/effects/registration.h"

namespace gc {
namespace {

const EffectInfo kInfo{
    "eccentricity",
    "Below the restoring torque the hub rests eccentric on the sleeve under its self-weight; "
    "the resulting misalignment fades (linearly by default) as the torque lifts and centres the hub.",
    "Sections 4.4 (eqs 49-53), 6.4 (Figures 14-15, Table 4)",
    {{"eccentric_misalignment_rad", "rad", "zeta_e, the misalignment at zero torque", 0.0, 0.01,
      0.0, 0.00105, {0.0, 0.3, RangeScale::jam_angle}},
     {"threshold_scale", "-", "s, the torque that centres the hub as a multiple of eqs 49-53's T_m",
      0.2, 3.0, 1.0, 1.0, {0.5, 2.0}, false, 0.0, {}, true},
     {"gravity_direction_rad", "rad", "direction of the sag, as beta", -2.0 * M_PI, 2.0 * M_PI, M_PI / 2,
      M_PI / 2, {-M_PI, M_PI}, false, 2.0 * M_PI},
     {"fade_sharpness", "-", "k, how abruptly the hub lifts off: 1 - (T / (s T_m))^k", 1.0, 20.0, 1.0, 1.0, {1.0, 10.0},
      true}}};

class Eccentricity final : public Effect {
 public:
  explicit Eccentricity(const ParameterValues& values)
      : Effect(kInfo, values),
        zeta_e_(value("eccentric_misalignment_rad")),
        scale_(value("threshold_scale")),
        direction_(value("gravity_direction_rad")),
        sharpness_(value("fade_sharpness")) {}

  void adjust_inputs(const MeasurementSample&, const ModelContext& context,
                     ModelState& state) const override {
    const double threshold = scale_ * context.restoring_torque_nm;
    if (state.point.torque_nm >= threshold) return;
    const double x = state.point.torque_nm / threshold;
    // k = 1 exactly as the linear fade, bit for bit.
    add_misalignment(zeta_e_ * (1.0 - (sharpness_ == 1.0 ? x : std::pow(x, sharpness_))), direction_, state.point);
  }

 private:
  double zeta_e_, scale_, direction_, sharpness_;
};

}  // namespace

EffectRegistration eccentricity_effect() { return register_effect<Eccentricity>(kInfo); }

}  // namespace gc
