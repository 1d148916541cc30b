#include "analysis/report_scale.h"

#include <algorithm>
#include <vector>

namespace gc::analysis {

namespace v1 = gearcoupling::v1;

double colour_scale_max_nm(const v1::ValidationResult& result) {
  double worst = 0.0;
  for (const v1::ModelValidation& model : result.models()) {
    for (const v1::ChannelErrorsRecord& cell : model.error_map().cells()) {
      for (const v1::ErrorMetricsRecord* channel : {&cell.msy(), &cell.msz()}) {
        if (channel->count() > 0) worst = std::max(worst, channel->rmse_nm());
      }
    }
  }
  return worst;
}

double noise_level_nm(const v1::ValidationResult& result) {
  std::vector<double> estimates;
  for (const v1::ModelValidation& model : result.models()) {
    if (model.compared_samples() == 0) continue;
    for (const v1::ErrorSignatureRecord& signature : model.signatures()) {
      estimates.push_back(signature.noise_estimate_nm());
    }
  }
  if (estimates.empty()) return 0.0;
  const auto middle = estimates.begin() + static_cast<std::ptrdiff_t>(estimates.size() / 2);
  std::nth_element(estimates.begin(), middle, estimates.end());
  if (estimates.size() % 2 == 1) return *middle;
  return 0.5 * (*middle + *std::max_element(estimates.begin(), middle));
}

}  // namespace gc::analysis
