#include "codec/model_file.h"

#include <cstdlib>

#include <google/protobuf/text_format.h>

#include "codec/bundled_data.h"
#include "codec/coupling_catalog.h"
#include "codec/nearest_name.h"
#include "codec/text_format.h"
#include "core/effects/effect_registry.h"
#include "core/model_error.h"
#include "idl/model_config.pb.h"

namespace gc::codec {
namespace {

namespace v1 = gearcoupling::v1;

// An error from the core or the coupling codec, re-raised under the model file's field path.
[[noreturn]] void rethrow_in(const InvalidInput& error, const std::string& field,
                             std::string_view source_name) {
  throw InvalidInput(field, std::string(source_name) + ": " + error.what());
}

CouplingDefinition coupling_of(const v1::ModelConfig& config, std::string_view source_name,
                               const std::filesystem::path& catalog_dir,
                               const std::filesystem::path& base_dir) {
  try {
    if (config.has_coupling_file()) {
      return load_coupling_geometry(base_dir / config.coupling_file()).definition();
    }
    if (!config.has_coupling()) {
      throw InvalidInput("model.coupling", "give coupling (a catalogue name) or coupling_file");
    }
    const auto catalog = load_coupling_catalog(catalog_dir);
    const auto found = catalog.find(config.coupling());
    if (found == catalog.end()) {
      std::string names;
      std::vector<std::string> known;
      for (const auto& [name, geometry] : catalog) {
        names += (names.empty() ? "" : ", ") + name;
        known.push_back(name);
      }
      throw InvalidInput("model.coupling", "'" + config.coupling() + "' is not in the catalogue " +
                                               catalog_dir.string() + " (" + names + ")" +
                                               did_you_mean(config.coupling(), known));
    }
    return found->second.definition();
  } catch (const InvalidInput& error) {
    rethrow_in(error, config.has_coupling_file() ? "model.coupling_file" : "model.coupling",
               source_name);
  }
}

std::vector<std::shared_ptr<const Effect>> effects_of(const v1::ModelConfig& config,
                                                      std::string_view source_name) {
  std::vector<std::shared_ptr<const Effect>> effects;
  for (int i = 0; i < config.effects_size(); ++i) {
    const v1::EffectConfig& entry = config.effects(i);
    const std::string field = "model.effects[" + std::to_string(i) + "]";
    for (const auto& previous : effects) {
      if (previous->name() == entry.name()) {
        throw InvalidInput(field + ".name", std::string(source_name) + ": effect '" +
                                                entry.name() + "' is given twice");
      }
    }
    ParameterValues values;
    for (int p = 0; p < entry.parameters_size(); ++p) {
      const v1::ParameterValue& parameter = entry.parameters(p);
      if (!values.emplace(parameter.name(), parameter.value()).second) {
        throw InvalidInput(field + ".parameters[" + std::to_string(p) + "]",
                           std::string(source_name) + ": parameter '" + parameter.name() +
                               "' of effect '" + entry.name() + "' is given twice");
      }
    }
    try {
      effects.push_back(make_effect(entry.name(), values));
    } catch (const InvalidInput& error) {
      // A misspelt effect ("eccentricty") gets the library's nearest name (issue 39).
      const std::string guess =
          error.field() == "effects." + entry.name() ? did_you_mean_effect(entry.name()) : "";
      // The core names "effects.<name>[.<parameter>]"; keep its tail after the index.
      const std::string tail = field + error.field().substr(std::string("effects").size());
      throw InvalidInput(tail, std::string(source_name) + ": " + error.what() + guess);
    }
  }
  return effects;
}

ContactOptions contact_of(const v1::ContactOptionsConfig& config) {
  ContactOptions options;
  if (config.has_slices()) options.slices = config.slices();
  if (config.has_load_sharing_tolerance()) {
    options.load_sharing.tolerance = config.load_sharing_tolerance();
  }
  if (config.has_load_sharing_max_iterations()) {
    options.load_sharing.max_iterations = config.load_sharing_max_iterations();
  }
  if (config.has_continuous_quarter_sums()) {
    options.continuous_quarter_sums = config.continuous_quarter_sums();
  }
  return options;
}

}  // namespace

ModelFile parse_model_text(std::string_view text, std::string_view source_name,
                           const std::filesystem::path& catalog_dir,
                           const std::filesystem::path& base_dir) {
  v1::ModelConfig config;
  parse_text_format(text, source_name, "model", config);
  CouplingDefinition coupling = coupling_of(config, source_name, catalog_dir, base_dir);
  auto effects = effects_of(config, source_name);
  try {
    return ModelFile{config.name(), config.description(),
                     config.has_coupling_file() ? config.coupling_file() : config.coupling(),
                     CouplingModel(coupling, std::move(effects), contact_of(config.contact()))};
  } catch (const InvalidInput& error) {
    rethrow_in(error, "model." + error.field(), source_name);
  }
}

ModelFile parse_model_json(std::string_view json, std::string_view source_name,
                           const std::filesystem::path& catalog_dir,
                           const std::filesystem::path& base_dir) {
  v1::ModelConfig message;
  return parse_model_text(text_format_from_json(json, source_name, "model", message), source_name,
                          catalog_dir, base_dir);
}

std::filesystem::path default_models_dir() {
  const char* dir = std::getenv("GEARCOUPLING_MODELS");
  return dir != nullptr && *dir != '\0' ? std::filesystem::path(dir) : bundled_data_dir("models");
}

ModelFile load_model_description(const std::filesystem::path& path,
                                 const std::filesystem::path& catalog_dir) {
  ModelFile file = parse_model_text(read_text_file(path, "model"), path.filename().string(),
                                    catalog_dir, path.parent_path());
  if (file.name.empty()) file.name = path.stem().string();
  return file;
}

CouplingModel load_model_file(const std::filesystem::path& path,
                              const std::filesystem::path& catalog_dir) {
  return load_model_description(path, catalog_dir).model;
}

std::string write_model_text(std::string_view name, std::string_view description,
                             std::string_view coupling, const CouplingModel& model) {
  v1::ModelConfig config;
  config.set_name(std::string(name));
  config.set_description(std::string(description));
  if (coupling.ends_with(".textproto")) {
    config.set_coupling_file(std::string(coupling));
  } else {
    config.set_coupling(std::string(coupling));
  }
  for (const auto& effect : model.effects()) {
    v1::EffectConfig* entry = config.add_effects();
    entry->set_name(effect->name());
    for (std::size_t i = 0; i < effect->values().size(); ++i) {
      v1::ParameterValue* parameter = entry->add_parameters();
      parameter->set_name(effect->info().parameters[i].name);
      parameter->set_value(effect->values()[i]);
    }
  }
  v1::ContactOptionsConfig* contact = config.mutable_contact();
  contact->set_slices(model.options().slices);
  contact->set_load_sharing_tolerance(model.options().load_sharing.tolerance);
  contact->set_load_sharing_max_iterations(model.options().load_sharing.max_iterations);
  contact->set_continuous_quarter_sums(model.options().continuous_quarter_sums);
  std::string text;
  google::protobuf::TextFormat::Printer printer;
  printer.PrintToString(config, &text);
  return "# gearcoupling model configuration (idl/model_config.proto, docs/recordings.md)\n" + text;
}

}  // namespace gc::codec
