// A model configuration that arrives from the network (a live model swap, docs/protocol.md,
// "Swapping the model"): the text and every name in it bounded in size, and no file of this
// host named, so a sender can neither make the reader read its files nor hold its memory.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string_view>

#include "codec/model_file.h"

namespace gc::codec {

/// The most a model text from the network may be or hold. A bundled model is under 1 kB and a
/// proposal's model (diagnose --write-model) a few kB; these leave room for hand-written ones.
struct ModelTextLimits {
  std::size_t text_bytes = 64 * 1024;        ///< the whole text
  std::size_t name_bytes = 128;              ///< ModelConfig.name
  std::size_t description_bytes = 1024;      ///< ModelConfig.description
  std::size_t coupling_bytes = 128;          ///< ModelConfig.coupling (a catalogue name)
  std::size_t effects = 32;                  ///< effects in the model
  std::size_t parameters = 64;               ///< parameters of one effect (an expression's terms)
  std::size_t parameter_name_bytes = 128;    ///< an effect's or a parameter's name
};

/// parse_model_text for a text no local user wrote: refuses `coupling_file` (a coupling comes
/// from `catalog_dir` by name; no path is opened) and anything beyond `limits`, before the
/// model is built. Throws gc::InvalidInput naming the field, its size and the allowed range,
/// and `source_name`; never quotes a file of this host.
ModelFile parse_untrusted_model_text(std::string_view text, std::string_view source_name,
                                     const std::filesystem::path& catalog_dir,
                                     const ModelTextLimits& limits = {});

}  // namespace gc::codec
