#include "clients/cli/model_flags.h"

#include <cstdlib>

#include "codec/bundled_data.h"

namespace gc::cli {

FlagSpec model_flag() {
  return {"model", "FILE|NAME",
          "model configuration: a .textproto file, or a name in data/models ($GEARCOUPLING_MODELS)",
          std::nullopt};
}

std::filesystem::path default_models_dir() {
  const char* dir = std::getenv("GEARCOUPLING_MODELS");
  return dir != nullptr && *dir != '\0' ? std::filesystem::path(dir)
                                        : codec::bundled_data_dir("models");
}

std::filesystem::path model_flag_path(const Flags& flags) {
  const std::string& model = flags.text("model");
  const bool is_file = model.find('/') != std::string::npos || model.ends_with(".textproto");
  return is_file ? std::filesystem::path(model) : default_models_dir() / (model + ".textproto");
}

codec::ModelFile load_model_flag(const Flags& flags) {
  return codec::load_model_description(model_flag_path(flags), flags.text("catalogue"));
}

}  // namespace gc::cli
