// validate's work, shared by the CLI (gearcoupling validate) and Python (gearcoupling.validate):
// a model, and with an added effect the model with it, through a recording; the result as data.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "analysis/validation_run.h"
#include "codec/model_file.h"
#include "idl/validation.pb.h"

namespace gc::analysis {

/// The effect --add names, against the model it is added to.
struct AddedEffect {
  std::shared_ptr<const Effect> effect;
  std::string label;  ///< "paper + friction", or "paper, friction replaced"
  std::string note;   ///< when it replaces the model's own effect: both specs; else empty
};

/// Parses `spec` (parse_effect_spec) against `model`. An effect the model already has with the
/// same parameters would compare the model with itself: FormatError. With other parameters it
/// replaces the model's, and `note` says so (docs/cli.md).
AddedEffect added_effect(std::string_view spec, const codec::ModelFile& model);

struct ModelValidation {
  std::optional<CouplingModel> with_added;   ///< the model with --add's effect
  std::string note;                          ///< added_effect's note, for the caller to show
  std::vector<ModelRun> runs;                ///< the model, then the one with the effect
  gearcoupling::v1::ValidationResult result;
};

/// T_ref of the errors in % when the user gives none: the model's own, its friction's
/// reference_torque_nm (a small coupling's 300 kN·m), else `fallback` (the library's 1.5 MN·m).
double model_reference_torque(const codec::ModelFile& model, double fallback);

/// Runs `model` (and, when `added_effect` is not empty, the model with that effect added, named
/// as added_effect labels it) through the recording at `path`. Errors as parse_effect_spec and
/// run_validation; the caller decides about require_compared_samples (it may print the notes first).
/// Returned by pointer: the runs point at the models inside.
std::unique_ptr<ModelValidation> validate_model(const std::filesystem::path& path,
                                                const codec::ModelFile& model,
                                                std::string_view added_effect,
                                                double reference_torque_nm,
                                                const ValidationRunOptions& options);

}  // namespace gc::analysis
