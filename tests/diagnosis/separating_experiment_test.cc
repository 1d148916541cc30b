// The separating experiment (diagnosis/separating_experiment.h) for a hysteresis that a recording
// without reversals cannot show: a torque ramp at one held misalignment, never travelled, where the
// paper's model with and without a lag predict the same. Only the loading direction parts them.
#include <gtest/gtest.h>

#include <numeric>
#include <vector>

#include "core/coupling_model.h"
#include "core/effects/effect_registry.h"
#include "diagnosis/separating_experiment.h"
#include "tests/core/nrel_couplings.h"

namespace gc {
namespace {

using testing::deg;
using testing::nrel_upwind;

CouplingModel paper(std::vector<std::shared_ptr<const Effect>> more = {}) {
  std::vector<std::shared_ptr<const Effect>> effects{make_effect("friction", {{"mu0", 0.1}}),
                                                     make_effect("pressure_angle_rotation"),
                                                     make_effect("self_weight")};
  effects.insert(effects.end(), more.begin(), more.end());
  return CouplingModel(nrel_upwind(), effects);
}

TEST(SeparatingExperiment, AHysteresisNeverTravelledIsToldApartByTheLoadingDirection) {
  const CouplingModel with_lag = paper({make_effect("hysteresis", {{"lag_rad", 1e-3}})});
  const CouplingModel without = paper();
  std::vector<RecordedSample> rows(200);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    MeasurementSample& s = rows[i].input;
    s.time_s = 0.1 * static_cast<double>(i);
    s.torque_nm = 3e5 + 6e3 * static_cast<double>(i);
    s.misalignment_rad = deg(0.3);
    s.direction_rad = deg(30.0);  // loading and travel 0: held from the start
    rows[i].measured = without.predict(s).moments;
  }
  std::vector<std::size_t> used(rows.size());
  std::iota(used.begin(), used.end(), 0u);
  const SeparatingExperiment experiment = separating_experiment(with_lag, without, rows, used, 500.0);
  EXPECT_EQ(experiment.input, "loading_direction") << experiment.advice;
  EXPECT_GT(experiment.difference_nm, 5.0 * 500.0) << experiment.advice;
}

}  // namespace
}  // namespace gc
