#include "clients/status/model_health.h"

#include <algorithm>

namespace gc::status {

ModelHealth channel_health(double systematic_nm, double noise_nm) {
  if (systematic_nm == 0.0 || systematic_nm < kAtNoiseLevelShare * noise_nm) {
    return ModelHealth::at_noise_level;
  }
  return systematic_nm >= kFarOffRatio * noise_nm ? ModelHealth::far_off : ModelHealth::systematic;
}

ModelHealth model_health(const ::gearcoupling::v1::ModelPeriodRecord& model,
                         std::uint64_t window_samples) {
  if (window_samples < 2) return ModelHealth::unknown;
  // The enumerators are ordered from good to bad.
  return std::max(channel_health(model.msy().systematic_nm(), model.msy().noise_nm()),
                  channel_health(model.msz().systematic_nm(), model.msz().noise_nm()));
}

std::string_view to_string(ModelHealth health) {
  switch (health) {
    case ModelHealth::unknown: return "unknown";
    case ModelHealth::at_noise_level: return "at_noise_level";
    case ModelHealth::systematic: return "systematic";
    case ModelHealth::far_off: return "far_off";
  }
  return "unknown";
}

}  // namespace gc::status
