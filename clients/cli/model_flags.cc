#include "clients/cli/model_flags.h"

#include <algorithm>
#include <string>
#include <system_error>
#include <vector>

#include "codec/nearest_name.h"

namespace gc::cli {

FlagSpec model_flag() {
  return {"model", "FILE|NAME",
          "model configuration: a .textproto file, or a name in data/models ($GEARCOUPLING_MODELS)",
          std::nullopt};
}

std::filesystem::path default_models_dir() { return codec::default_models_dir(); }

std::vector<std::string> bundled_model_names() {
  std::vector<std::string> names;
  std::error_code error;
  for (const auto& entry : std::filesystem::directory_iterator(default_models_dir(), error)) {
    if (entry.path().extension() == ".textproto") names.push_back(entry.path().stem().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

namespace {

std::string joined(const std::vector<std::string>& names) {
  std::string text;
  for (const std::string& name : names) text += (text.empty() ? "" : ", ") + name;
  return text.empty() ? "none found" : text;
}

}  // namespace

std::filesystem::path model_flag_path(const Flags& flags) {
  const std::string& model = flags.text("model");
  const bool is_file = model.find('/') != std::string::npos || model.ends_with(".textproto");
  if (is_file) return model;
  const std::filesystem::path bundled = default_models_dir() / (model + ".textproto");
  // A misspelt name ("papr") gets the names there are, not a missing file's path (issue 39).
  if (!std::filesystem::exists(bundled)) {
    const std::vector<std::string> names = bundled_model_names();
    throw UsageError("--model '" + model + "': no such bundled model (" + joined(names) +
                     ") nor a .textproto file" + codec::did_you_mean(model, names));
  }
  return bundled;
}

codec::ModelFile load_model_flag(const Flags& flags) {
  return codec::load_model_description(model_flag_path(flags), flags.text("catalogue"));
}

}  // namespace gc::cli
