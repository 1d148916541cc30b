// The model a test cell is compared with: a model file's text checked as `validate --model`
// checks a file (codec/model_file.h), with the time it came into force.
#pragma once

#include <chrono>
#include <filesystem>
#include <memory>
#include <string>
#include <string_view>

#include "core/coupling_model.h"

namespace gc::live {

struct CellModel {
  std::string name;                              ///< ModelConfig.name, or the file's stem
  std::string description;                       ///< ModelConfig.description
  std::string coupling;                          ///< the catalogue name, as written
  std::shared_ptr<const CouplingModel> model;
  std::chrono::system_clock::time_point since;   ///< when it came into force
};

/// Parses a model swap's text (codec::parse_untrusted_model_text: couplings from `catalog_dir`,
/// `coupling_file` refused without a look at the path, every size bounded). Throws
/// gc::InvalidInput naming the field and `source_name` for anything `validate --model` refuses
/// and anything beyond codec::ModelTextLimits.
CellModel parse_cell_model(std::string_view text, std::string_view source_name,
                           const std::filesystem::path& catalog_dir);

/// A model file, or the name of one bundled in data/models/, like `--model`.
CellModel load_cell_model(const std::string& file_or_name, const std::filesystem::path& models_dir,
                          const std::filesystem::path& catalog_dir);

}  // namespace gc::live
