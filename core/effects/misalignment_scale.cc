// A scale error of the misalignment measurement: the displacement sensors' calibration slope, or
// the lever arm that turns their readings into an angle, makes the recorded zeta a share of the
// misalignment the coupling sees (Section 3: the misalignment is derived from proximity-probe
// readings over a known axial distance). The coupling sees zeta_true = (1 + k) zeta_measured.
#include "core/effects/registration.h"

namespace gc {
namespace {

const EffectInfo kInfo{
    "misalignment_scale",
    "A misalignment scale error of the displacement sensors or of their lever arm: the coupling "
    "sees (1 + k) times the measured misalignment.",
    "Section 3 (instrumentation: misalignment from displacement sensors)",
    {{"scale_error", "-", "k, the misalignment the coupling sees over the measured, less 1", -0.5, 1.0, 0.0,
      0.0, {-0.2, 0.2}}}};

class MisalignmentScale final : public Effect {
 public:
  explicit MisalignmentScale(const ParameterValues& values) : Effect(kInfo, values), k_(value("scale_error")) {}

  void adjust_inputs(const MeasurementSample&, const ModelContext&, ModelState& state) const override {
    state.point.misalignment_rad *= 1.0 + k_;
  }

 private:
  double k_;
};

}  // namespace

EffectRegistration misalignment_scale_effect() { return register_effect<MisalignmentScale>(kInfo); }

}  // namespace gc
