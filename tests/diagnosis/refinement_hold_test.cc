// A refinement holds what the data cannot determine at the model's own value: friction's
// reference_torque_nm enters only as mu_low_torque * T_ref, so it is held; held at the library's
// 1.5 MN·m it reached --add and --write-model for a coupling whose model file says 120 kN·m.
#include <gtest/gtest.h>

#include "diagnosis/effect_fit.h"
#include "core/effects/effect_registry.h"
#include "diagnosis/synthesis/synthesize.h"
#include "tests/core/nrel_couplings.h"
#include "tests/diagnosis/hidden_effect_scenarios.h"

namespace gc {
namespace {

const EffectRegistration& friction_registration() {
  static const std::vector<EffectRegistration> registry = effect_registry();
  for (const EffectRegistration& r : registry) if (r.info->name == "friction") return r;
  throw std::logic_error("no friction in the registry");
}

TEST(RefinementHold, AnUnidentifiableParameterKeepsTheModelsValue) {
  const CouplingModel paper(testing::nrel_upwind(), testing::paper_effects());
  const CouplingModel given = paper.with_effect(make_effect("friction", {{"mu0", 0.1}, {"reference_torque_nm", 1.2e5}}));
  const CouplingModel truth = paper.with_effect(
      make_effect("friction", {{"mu0", 0.1}, {"mu_low_torque", 0.05}, {"reference_torque_nm", 1.2e5}}));
  const SynthesizedRecording recording =
      synthesize(truth, testing::paper_sequence(testing::nrel_upwind(), LoadSequenceKind::torque_ramp), {2000.0, 3});
  std::vector<std::size_t> rows(recording.samples.size());
  for (std::size_t i = 0; i < rows.size(); ++i) rows[i] = i;
  const std::optional<EffectFit> fit = fit_effect(given, friction_registration(), recording.samples, rows, serial_for(),
                                                  FitSettings{}, given.effect("friction").get());
  ASSERT_TRUE(fit.has_value());
  for (const ParameterEstimate& p : fit->parameters) {
    if (p.name == "reference_torque_nm") {
      EXPECT_TRUE(p.held) << p.note;
      EXPECT_NEAR(p.value, 1.2e5, 1e-6 * 1.2e5) << p.note;
      EXPECT_NE(p.note.find("the model's value"), std::string::npos) << p.note;
    }
    if (p.name == "mu_low_torque") { EXPECT_NEAR(p.value, 0.05, 0.01); }
  }
  EXPECT_NEAR(fit->effect->value("reference_torque_nm"), 1.2e5, 1e-6 * 1.2e5);
}

}  // namespace
}  // namespace gc
