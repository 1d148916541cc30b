#include "analysis/model_validation.h"

#include <fmt/format.h>

#include "analysis/effect_spec.h"
#include "analysis/format_error.h"
#include "analysis/validation_result.h"

namespace gc::analysis {

AddedEffect added_effect(std::string_view spec, const codec::ModelFile& model) {
  std::shared_ptr<const Effect> effect = parse_effect_spec(spec);
  const std::shared_ptr<const Effect> existing = model.model.effect(effect->name());
  if (existing == nullptr) return {effect, model.name + " + " + effect->name(), ""};
  const std::string had = effect_spec_text(*existing);
  if (existing->values() == effect->values()) {
    throw FormatError(fmt::format("--add {}: model {} already has {} with these parameters ({}): "
                                  "the comparison would change nothing",
                                  spec, model.name, effect->name(), had));
  }
  return {effect, model.name + ", " + effect->name() + " replaced",
          fmt::format("model {} already has {} ({}); --add replaces it with {}", model.name,
                      effect->name(), had, effect_spec_text(*effect))};
}

double model_reference_torque(const codec::ModelFile& model, double fallback) {
  const std::shared_ptr<const Effect> friction = model.model.effect("friction");
  return friction ? friction->value("reference_torque_nm") : fallback;
}

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
    const AddedEffect added = analysis::added_effect(added_effect, model);
    validation->note = added.note;
    validation->with_added.emplace(model.model.with_effect(added.effect));
    runs.push_back({added.label, &*validation->with_added, ValidationAccumulator(binning),
                    PointSampler()});
  }
  const RecordingSummary recording = run_validation(path, runs, options);
  validation->result = validation_result(recording, runs, binning);
  return validation;
}

}  // namespace gc::analysis
