#include "core/tooth_stiffness.h"

namespace gc {

double elasticity_factor(double form_factor) { return form_factor / (0.76 + 7.25 * form_factor); }

double single_pair_stiffness(double facewidth_m, double youngs_modulus_pa, double form_factor_hub,
                             double form_factor_sleeve) {
  const double z1 = elasticity_factor(form_factor_hub);
  const double z2 = elasticity_factor(form_factor_sleeve);
  return facewidth_m * youngs_modulus_pa * z1 * z2 / (z1 + z2);
}

}  // namespace gc
