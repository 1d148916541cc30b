// The bundled models the validation tests run on, and models with one extra effect.
#pragma once

#include <string>

#include "codec/model_file.h"

namespace gc::testing {

inline codec::ModelFile bundled_model(const std::string& name) {
  return codec::load_model_description(std::string(GC_BUNDLED_MODELS_DIR) + "/" + name + ".textproto",
                                       GC_BUNDLED_CATALOG_DIR);
}

/// The bundled model `name` with `extra` (model-file text of one effects entry) appended.
inline codec::ModelFile model_with(const std::string& name, const std::string& extra) {
  const codec::ModelFile base = bundled_model(name);
  const std::string text =
      codec::write_model_text(base.name + "_plus", "", base.coupling, base.model) + extra;
  return codec::parse_model_text(text, "test", GC_BUNDLED_CATALOG_DIR, ".");
}

}  // namespace gc::testing
