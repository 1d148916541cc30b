#include "tests/diagnosis/independent/base_models.h"

#include "core/effects/effect_registry.h"
#include "tests/core/nrel_couplings.h"

namespace gc::independent {

CouplingModel paper_model(const std::string& without) {
  std::vector<std::shared_ptr<const Effect>> effects;
  for (const std::string name : {"friction", "pressure_angle_rotation", "self_weight"}) {
    if (name != without) effects.push_back(make_effect(name));
  }
  return CouplingModel(testing::nrel_upwind(), effects);
}

}  // namespace gc::independent
