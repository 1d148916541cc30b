// --model: a model configuration file (idl/model_config.proto), or the name of one bundled in
// data/models/ ("paper" is data/models/paper.textproto).
#pragma once

#include "clients/cli/command_line.h"
#include <memory>
#include <string>

#include "codec/model_file.h"
#include "core/effects/effect.h"

namespace gc::cli {

/// The flag spec of --model (required).
FlagSpec model_flag();

/// Loads the model named by --model, couplings from --catalogue. Throws gc::InvalidInput naming
/// the field and file.
codec::ModelFile load_model_flag(const Flags& flags);

/// The effect --add names, and the label of the model with it.
struct AddedEffect {
  std::shared_ptr<const Effect> effect;
  std::string label;  ///< "paper + friction", or "paper, friction replaced"
};

/// Parses --add `spec` against `model`. An effect the model already has with the same
/// parameters would compare the model with itself: UsageError. With other parameters it
/// replaces the model's: a note on standard error says so, with both specs (docs/cli.md).
AddedEffect added_effect(const std::string& spec, const codec::ModelFile& model);

/// $GEARCOUPLING_MODELS when set and not empty, else the bundled data/models.
std::filesystem::path default_models_dir();

}  // namespace gc::cli
