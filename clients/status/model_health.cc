#include "clients/status/model_health.h"

#include <algorithm>

namespace gc::status {

namespace {

ModelHealth channel_health(double systematic_nm, double noise_nm, double at_noise_share,
                           double far_off_ratio) {
  if (systematic_nm == 0.0 || systematic_nm < at_noise_share * noise_nm) {
    return ModelHealth::at_noise_level;
  }
  return systematic_nm >= far_off_ratio * noise_nm ? ModelHealth::far_off : ModelHealth::systematic;
}

}  // namespace

ModelHealth channel_health(double systematic_nm, double noise_nm) {
  return channel_health(systematic_nm, noise_nm, kAtNoiseLevelShare, kFarOffRatio);
}

ModelHealth model_health(const ::gearcoupling::v1::ModelPeriodRecord& model,
                         std::uint64_t window_samples, ModelHealth previous) {
  if (window_samples < 2) return ModelHealth::unknown;
  const double share = previous == ModelHealth::at_noise_level ? kAtNoiseLevelShare / kHysteresis
                                                               : kAtNoiseLevelShare;
  const double far = previous == ModelHealth::far_off ? kHysteresis * kFarOffRatio : kFarOffRatio;
  return std::max(channel_health(model.msy().systematic_nm(), model.msy().noise_nm(), share, far),
                  channel_health(model.msz().systematic_nm(), model.msz().noise_nm(), share, far));
}

ModelHealth model_health_from(std::string_view text) {
  for (const ModelHealth health : {ModelHealth::at_noise_level, ModelHealth::systematic,
                                   ModelHealth::far_off, ModelHealth::unit_error}) {
    if (text == to_string(health)) return health;
  }
  return ModelHealth::unknown;
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
    case ModelHealth::unit_error: return "unit_error";
  }
  return "unknown";
}

}  // namespace gc::status
