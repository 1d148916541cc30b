#include "live/cell_model.h"


#include "codec/model_file.h"
#include "codec/untrusted_model_text.h"
#include "core/model_error.h"

namespace gc::live {
namespace {

CellModel from_file(codec::ModelFile file) {
  return {file.name, file.description, file.coupling,
          std::make_shared<const CouplingModel>(std::move(file.model)),
          std::chrono::system_clock::now()};
}

}  // namespace

CellModel parse_cell_model(std::string_view text, std::string_view source_name,
                           const std::filesystem::path& catalog_dir) {
  // A swap's text comes from the network: bounded, and it names no file of this host.
  codec::ModelFile file = codec::parse_untrusted_model_text(text, source_name, catalog_dir);
  return from_file(std::move(file));
}

CellModel load_cell_model(const std::string& file_or_name, const std::filesystem::path& models_dir,
                          const std::filesystem::path& catalog_dir) {
  // As the CLI's --model: a path names a file, a bare name a bundled model.
  const bool is_file =
      file_or_name.find('/') != std::string::npos || file_or_name.ends_with(".textproto");
  const std::filesystem::path path =
      is_file ? std::filesystem::path(file_or_name) : models_dir / (file_or_name + ".textproto");
  codec::ModelFile file = codec::load_model_description(path, catalog_dir);
  return from_file(std::move(file));
}

}  // namespace gc::live
