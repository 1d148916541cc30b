#include "clients/cli/model_flags.h"

#include <cstdlib>

#include <fmt/format.h>

#include "analysis/effect_spec.h"
#include "codec/bundled_data.h"

namespace gc::cli {

FlagSpec model_flag() {
  return {"model", "FILE|NAME",
          "model configuration: a .textproto file, or a name in data/models ($GEARCOUPLING_MODELS)",
          std::nullopt};
}

AddedEffect added_effect(const std::string& spec, const codec::ModelFile& model) {
  std::shared_ptr<const Effect> effect = analysis::parse_effect_spec(spec);
  const std::shared_ptr<const Effect> existing = model.model.effect(effect->name());
  if (existing == nullptr) return {effect, model.name + " + " + effect->name()};
  const std::string had = analysis::effect_spec_text(*existing);
  if (existing->values() == effect->values()) {
    throw UsageError(fmt::format("--add {}: model {} already has {} with these parameters ({}): "
                                 "the comparison would change nothing",
                                 spec, model.name, effect->name(), had));
  }
  fmt::print(stderr, "gearcoupling validate: note: model {} already has {} ({}); --add replaces "
             "it with {}\n", model.name, effect->name(), had, analysis::effect_spec_text(*effect));
  return {effect, model.name + ", " + effect->name() + " replaced"};
}

std::filesystem::path default_models_dir() {
  const char* dir = std::getenv("GEARCOUPLING_MODELS");
  return dir != nullptr && *dir != '\0' ? std::filesystem::path(dir)
                                        : codec::bundled_data_dir("models");
}

codec::ModelFile load_model_flag(const Flags& flags) {
  const std::string& model = flags.text("model");
  const bool is_file = model.find('/') != std::string::npos || model.ends_with(".textproto");
  const std::filesystem::path path =
      is_file ? std::filesystem::path(model) : default_models_dir() / (model + ".textproto");
  return codec::load_model_description(path, flags.text("catalogue"));
}

}  // namespace gc::cli
