// The couplings and model files of the zoo: the two bundled NREL couplings with the paper's
// models, and scaled variants written here (other tooth counts, pitch diameter and module, face
// width, crown radius, pressure angle, backlash, weights), each with the paper's effects. The
// recording's truth is exactly the model diagnose is given.
#pragma once

#include <cstdint>
#include <filesystem>
#include <memory>
#include <string>

#include "core/coupling_model.h"
#include "tests/diagnosis/zoo/rng.h"

namespace gc::zoo {

struct ModelChoice {
  std::string name;             ///< the model's name
  std::string model_text;       ///< the model file (textproto)
  std::string coupling_text;    ///< the coupling file it names (coupling_file: "coupling.textproto"); empty for a bundled one
  std::string description;      ///< e.g. "nrel_upwind" or "scaled N 84 D 0.72 m F 0.09 m R_F 1.9 m phi 22.5"
  double torque_scale = 1.0;    ///< torque capacity relative to the NREL couplings (D^2 F)
};

/// A bundled coupling with probability `bundled_share`, else a scaled variant.
ModelChoice draw_model(Rng& rng, double bundled_share = 0.5);

/// The model a choice describes, loaded through the codec as the CLI loads it (the files written
/// to a private temporary directory and read back). Throws gc::InvalidInput when it does not load.
std::shared_ptr<const CouplingModel> load_choice(const ModelChoice& choice);

/// Writes the model (and its coupling file) into `dir`; returns the model file's path.
std::filesystem::path write_choice(const ModelChoice& choice, const std::filesystem::path& dir);

}  // namespace gc::zoo
