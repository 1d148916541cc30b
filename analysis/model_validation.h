// validate's work, shared by the CLI (gearcoupling validate) and Python (gearcoupling.validate):
// a model, and with an added effect the model with it, through a recording; the result as data.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string_view>
#include <vector>

#include "analysis/validation_run.h"
#include "codec/model_file.h"
#include "idl/validation.pb.h"

namespace gc::analysis {

struct ModelValidation {
  std::optional<CouplingModel> with_added;   ///< the model with --add's effect
  std::vector<ModelRun> runs;                ///< the model, then the one with the effect
  gearcoupling::v1::ValidationResult result;
};

/// Runs `model` (and, when `added_effect` is not empty, the model with that effect added, named
/// "<name> + <effect>") through the recording at `path`. Errors as parse_effect_spec and
/// run_validation; the caller decides about require_compared_samples (it may print the notes first).
/// Returned by pointer: the runs point at the models inside.
std::unique_ptr<ModelValidation> validate_model(const std::filesystem::path& path,
                                                const codec::ModelFile& model,
                                                std::string_view added_effect,
                                                double reference_torque_nm,
                                                const ValidationRunOptions& options);

}  // namespace gc::analysis
