#include "codec/untrusted_model_text.h"

#include <string>

#include "codec/text_format.h"
#include "core/model_error.h"
#include "idl/model_config.pb.h"

namespace gc::codec {
namespace {

/// Throws InvalidInput naming `field` when `size` is beyond `most`: "<field> has N bytes (or
/// items), allowed 0 to M".
void require_at_most(std::string_view source_name, const std::string& field, std::size_t size,
                     std::size_t most, const char* unit) {
  if (size <= most) return;
  throw InvalidInput(field, std::string(source_name) + ": " + std::to_string(size) + " " + unit +
                                ", allowed 0 to " + std::to_string(most));
}

void check_bounds(const gearcoupling::v1::ModelConfig& config, std::string_view source_name,
                  const ModelTextLimits& limits) {
  if (config.has_coupling_file()) {
    // Not even looked at: whether the path exists, and what it holds, stay on this host.
    throw InvalidInput("model.coupling_file",
                       std::string(source_name) + ": refused; a model from the network names "
                       "its coupling from the catalogue (coupling: \"NAME\"), never a file");
  }
  require_at_most(source_name, "model.name", config.name().size(), limits.name_bytes, "bytes");
  require_at_most(source_name, "model.description", config.description().size(),
                  limits.description_bytes, "bytes");
  require_at_most(source_name, "model.coupling", config.coupling().size(), limits.coupling_bytes,
                  "bytes");
  require_at_most(source_name, "model.effects", static_cast<std::size_t>(config.effects_size()),
                  limits.effects, "effects");
  for (int i = 0; i < config.effects_size(); ++i) {
    const auto& effect = config.effects(i);
    const std::string field = "model.effects[" + std::to_string(i) + "]";
    require_at_most(source_name, field + ".name", effect.name().size(), limits.parameter_name_bytes,
                    "bytes");
    require_at_most(source_name, field + ".parameters",
                    static_cast<std::size_t>(effect.parameters_size()), limits.parameters,
                    "parameters");
    for (int p = 0; p < effect.parameters_size(); ++p) {
      require_at_most(source_name, field + ".parameters[" + std::to_string(p) + "].name",
                      effect.parameters(p).name().size(), limits.parameter_name_bytes, "bytes");
    }
  }
}

}  // namespace

ModelFile parse_untrusted_model_text(std::string_view text, std::string_view source_name,
                                     const std::filesystem::path& catalog_dir,
                                     const ModelTextLimits& limits) {
  // Before parsing: a 10 MB text costs its parse (and the strings it holds) otherwise.
  require_at_most(source_name, "model", text.size(), limits.text_bytes, "bytes of model text");
  gearcoupling::v1::ModelConfig config;
  parse_text_format(text, source_name, "model", config);
  check_bounds(config, source_name, limits);
  // Checked: no coupling_file, so no base directory is ever used.
  return parse_model_text(text, source_name, catalog_dir, std::filesystem::path());
}

}  // namespace gc::codec
