// The continuous form of eqs 42-43's quarter sums and eq 13's residue (docs/model.md): the
// paper's int(qN/4) makes |M| a sawtooth in torque and misalignment with steps of 6-8 %, which a
// real coupling does not have. As an effect, the switch is a model part the diagnosis can try like
// any other, so that measurements that prefer the continuous form say so instead of bending some
// other effect's parameters to follow the saw. No parameters: it is on or off.
#include "core/effects/registration.h"

namespace gc {
namespace {

const EffectInfo kInfo{
    "continuous_quarter_sums",
    "The induced moments without the sawtooth of the paper's quarter sums (eqs 13, 42-43 in their "
    "continuous form): the coupling's moment grows smoothly as teeth enter contact.",
    "Section 4.3 (eqs 42-43), docs/model.md",
    {}};

class ContinuousQuarterSums final : public Effect {
 public:
  explicit ContinuousQuarterSums(const ParameterValues& values) : Effect(kInfo, values) {}

  void adjust_inputs(const MeasurementSample&, const ModelContext&, ModelState& state) const override {
    state.contact.continuous_quarter_sums = true;
  }
};

}  // namespace

EffectRegistration continuous_quarter_sums_effect() { return register_effect<ContinuousQuarterSums>(kInfo); }

}  // namespace gc
