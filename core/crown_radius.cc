#include "core/crown_radius.h"

#include "core/model_error.h"

namespace gc {

double crown_radius_from_lead_modification(double facewidth_m, double lead_modification_m) {
  require_positive("coupling.facewidth_m", facewidth_m);
  require_positive("coupling.lead_modification_m", lead_modification_m);
  const double half_face = 0.5 * facewidth_m;
  if (lead_modification_m >= half_face) {
    throw InvalidInput("coupling.lead_modification_m", lead_modification_m,
                       "(0, F/2) for a circular crown");
  }
  return (half_face * half_face + lead_modification_m * lead_modification_m) /
         (2.0 * lead_modification_m);
}

}  // namespace gc
