// Model configuration files: gearcoupling.v1.ModelConfig (idl/model_config.proto) in protobuf
// text format, as bundled in data/models/. A coupling from the catalogue or a file, and the
// effects of the library (core/effects/) in order, with their parameters in SI.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "core/coupling_model.h"

namespace gc::codec {

/// A model and what its file says about it.
struct ModelFile {
  std::string name;          ///< ModelConfig.name, or the file's stem when empty
  std::string description;
  std::string coupling;      ///< the catalogue name or coupling file as written
  CouplingModel model;
};

/// Parses a model configuration. Couplings named by `coupling` come from `catalog_dir`, those
/// given by `coupling_file` are read relative to `base_dir`. Throws gc::InvalidInput naming
/// the field ("model.effects[1].friction.mu0", "model.coupling", ...) and `source_name` for a
/// syntax error, an unknown effect or parameter, a value outside its bounds, an effect given
/// twice or a coupling that cannot be found or is not physical.
ModelFile parse_model_text(std::string_view text, std::string_view source_name,
                           const std::filesystem::path& catalog_dir,
                           const std::filesystem::path& base_dir);

/// Parses a model configuration given as JSON with the file's fields (protobuf's JSON mapping of
/// gearcoupling.v1.ModelConfig, e.g. a Python dict): the same checks and errors as the text.
ModelFile parse_model_json(std::string_view json, std::string_view source_name,
                           const std::filesystem::path& catalog_dir,
                           const std::filesystem::path& base_dir);

/// $GEARCOUPLING_MODELS when set and not empty, else the bundled models
/// (bundled_data_dir("models")): where a model named without a path is looked up.
std::filesystem::path default_models_dir();

/// Reads and parses `path`; errors name the file by its file name.
ModelFile load_model_description(const std::filesystem::path& path,
                                 const std::filesystem::path& catalog_dir);
CouplingModel load_model_file(const std::filesystem::path& path,
                              const std::filesystem::path& catalog_dir);

/// `model` as a model configuration file that load_model_file reads back to the same model:
/// every effect with every parameter written out, in order. `coupling` is the catalogue name
/// (or coupling file) to refer to.
std::string write_model_text(std::string_view name, std::string_view description,
                             std::string_view coupling, const CouplingModel& model);

}  // namespace gc::codec
