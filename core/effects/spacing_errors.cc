// Tooth spacing errors (Section 6.4: the upwind sleeve "is not perfectly round ... which can
// also cause tooth spacing errors across the circumference"; Tjernberg, Wink and Nakandakari
// in Section 1). A lumped spacing error e adds to the tooth separation z_o of eq 11, so fewer
// teeth share the load even when aligned.
#include "core/effects/registration.h"

namespace gc {
namespace {

const EffectInfo kInfo{
    "spacing_errors",
    "Unequal tooth spacing leaves some teeth out of contact: the load concentrates on fewer "
    "teeth, as a larger separation z_o would.",
    "Sections 1, 4 (equal-spacing assumption), 6.4",
    {{"spacing_error_m", "m", "e, added to eq 11's z_o", 0.0, 1e-4, 0.0, 1e-5, {0.0, 5e-5}}}};

class SpacingErrors final : public Effect {
 public:
  explicit SpacingErrors(const ParameterValues& values)
      : Effect(kInfo, values), error_(value("spacing_error_m")) {}

  void adjust_inputs(const MeasurementSample&, const ModelContext&,
                     ModelState& state) const override {
    state.contact.spacing_error_m += error_;
  }

 private:
  double error_;
};

}  // namespace

EffectRegistration spacing_errors_effect() { return register_effect<SpacingErrors>(kInfo); }

}  // namespace gc
