// Shaft and rim compliance (Section 6.1): the FE/CM model, which includes the flexibility of
// rim and shaft, finds more teeth in contact and a larger jam angle than the rigid-shaft
// analytic model. Lumped here as a factor k on the single-pair stiffness C of eq 5 (applied
// through E, so the Hertz estimate softens with it).
#include "core/effects/registration.h"

namespace gc {
namespace {

const EffectInfo kInfo{
    "compliance",
    "Rim and shaft flexibility in series with the teeth: a softer mesh spreads the load over "
    "more teeth (eqs 20-22 with a smaller C).",
    "Section 4 (rigid-shaft assumption), 6.1 (FE/CM against analytic)",
    {{"stiffness_factor", "-", "k, the mesh stiffness as a share of eq 5's C", 0.1, 1.0, 1.0,
      0.7, {0.6, 1.0}}}};

class Compliance final : public Effect {
 public:
  explicit Compliance(const ParameterValues& values)
      : Effect(kInfo, values), factor_(value("stiffness_factor")) {}

  void adjust_coupling(CouplingDefinition& coupling) const override {
    coupling.youngs_modulus_pa *= factor_;  // C = F E Z1 Z2 / (Z1 + Z2) scales with E
  }

 private:
  double factor_;
};

}  // namespace

EffectRegistration compliance_effect() { return register_effect<Compliance>(kInfo); }

}  // namespace gc
