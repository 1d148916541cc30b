#include "analysis/model_validation.h"

#include "analysis/effect_spec.h"
#include "analysis/validation_result.h"

namespace gc::analysis {

std::unique_ptr<ModelValidation> validate_model(const std::filesystem::path& path,
                                                const codec::ModelFile& model,
                                                std::string_view added_effect,
                                                double reference_torque_nm,
                                                const ValidationRunOptions& options) {
  BinningOptions binning;
  binning.reference_torque_nm = reference_torque_nm;
  binning.jam_angle_rad = model.model.geometry().jam_angle().angle_rad;
  auto validation = std::make_unique<ModelValidation>();
  std::vector<ModelRun>& runs = validation->runs;
  runs.push_back({model.name, &model.model, ValidationAccumulator(binning), PointSampler()});
  if (!added_effect.empty()) {
    const auto effect = parse_effect_spec(added_effect);
    validation->with_added.emplace(model.model.with_effect(effect));
    runs.push_back({model.name + " + " + effect->name(), &*validation->with_added,
                    ValidationAccumulator(binning), PointSampler()});
  }
  const RecordingSummary recording = run_validation(path, runs, options);
  validation->result = validation_result(recording, runs, binning);
  return validation;
}

}  // namespace gc::analysis
