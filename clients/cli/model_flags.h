// --model: a model configuration file (idl/model_config.proto), or the name of one bundled in
// data/models/ ("paper" is data/models/paper.textproto).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "clients/cli/command_line.h"
#include "codec/model_file.h"

namespace gc::cli {

/// The flag spec of --model (required).
FlagSpec model_flag();

/// Loads the model named by --model, couplings from --catalogue. Throws gc::InvalidInput naming
/// the field and file.
codec::ModelFile load_model_flag(const Flags& flags);

/// The file --model names: itself when it is a path (has a '/' or ends in .textproto), else
/// the bundled model of that name.
std::filesystem::path model_flag_path(const Flags& flags);

/// $GEARCOUPLING_MODELS when set and not empty, else the bundled data/models.
std::filesystem::path default_models_dir();

/// The names --model takes besides a file: the stems of default_models_dir()'s *.textproto,
/// sorted.
std::vector<std::string> bundled_model_names();

}  // namespace gc::cli
