#include "clients/python/model_argument.h"

#include <filesystem>
#include <optional>

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "analysis/atomic_file.h"
#include "analysis/effect_spec.h"
#include "calculators/coupling_reference.h"
#include "clients/python/bindings.h"
#include "clients/python/typed_objects.h"
#include "clients/python/predictions.h"
#include "codec/coupling_catalog.h"
#include "core/model_error.h"

namespace py = pybind11;

namespace gc::python {

Model with_effect(const Model& model, const std::string& spec) {
  codec::ModelFile file = *model.file;
  file.model = file.model.with_effect(analysis::parse_effect_spec(spec));
  return {std::make_shared<const codec::ModelFile>(std::move(file))};
}

Model model_argument(py::handle argument) {
  if (py::isinstance<Model>(argument)) return argument.cast<Model>();
  const std::filesystem::path catalog = codec::default_catalog_dir();
  if (py::isinstance<py::dict>(argument)) {
    const std::string json = py::str(py::module_::import("json").attr("dumps")(argument));
    return {std::make_shared<const codec::ModelFile>(
        codec::parse_model_json(json, "model dict", catalog, std::filesystem::current_path()))};
  }
  std::filesystem::path path;
  if (py::isinstance<py::str>(argument) && !calculators::is_file_reference(argument.cast<std::string>())) {
    path = codec::default_models_dir() / (argument.cast<std::string>() + ".textproto");
  } else {
    path = argument.cast<std::filesystem::path>();
  }
  return {std::make_shared<const codec::ModelFile>(codec::load_model_description(path, catalog))};
}

std::string model_text(const codec::ModelFile& file) {
  return codec::write_model_text(file.name, file.description, file.coupling, file.model);
}

void bind_models(py::module_& m) {
  py::class_<Model>(m, "Model",
                    "A model: a coupling and the effects of the library in order (idl/model_config.proto).")
      .def(py::init([](const ModelArgument& source) { return model_argument(source); }),
           py::arg("source"),
           "A bundled model's name ('paper'; $GEARCOUPLING_MODELS), a model file (.textproto), or a "
           "dict with the model file's fields (couplings by catalogue name; coupling_file relative "
           "to the working directory).")
      .def_property_readonly("name", [](const Model& model) { return model.file->name; })
      .def_property_readonly("description", [](const Model& model) { return model.file->description; })
      .def_property_readonly("coupling", [](const Model& model) { return model.file->coupling; },
                             "The catalogue name or coupling file the model names.")
      .def_property_readonly("effects",
                             [](const Model& model) {
                               std::vector<std::string> names;
                               for (const auto& effect : model.file->model.effects()) names.push_back(effect->name());
                               return names;
                             },
                             "The effects' names, in the order they act.")
      .def("effect_parameters",
           [](const Model& model, const std::string& name) {
             const auto effect = model.file->model.effect(name);
             if (!effect) throw InvalidInput("effects." + name, "the model has no effect named \"" + name + "\"");
             py::dict parameters;
             for (std::size_t i = 0; i < effect->values().size(); ++i) {
               parameters[py::str(effect->info().parameters[i].name)] = effect->values()[i];
             }
             return parameters;
           },
           py::arg("name"), "The effect's parameters by name, in SI (their names carry the unit).")
      .def("with_effect", &with_effect, py::arg("spec"),
           "This model with one more effect (or that effect replaced): 'EFFECT[=parameter=value,...]', "
           "SI parameters, e.g. 'hysteresis=lag_rad=6e-4', as validate --add takes it.")
      .def("predict",
           [](const Model& model, const RecordingArgument& recording,
              const ColumnsArgument& columns, const NegateArgument& negate, unsigned threads) {
             return predict_recording(model, read_recording(recording, columns, negate), threads);
           },
           py::arg("recording"), py::kw_only(), py::arg("columns") = py::none(),
           py::arg("negate") = py::none(), py::arg("threads") = 0u,
           "The model's prediction of every sample of the recording (a file, a DataFrame or a "
           "Recording), as validate makes it (CouplingModel::predict_at: input timing such as "
           "moment_delay included). Returns a CaseTable (.to_frame() for pandas): time_s, "
           "torque_nm, misalignment_rad, direction_rad, msy_measured_nm, msz_measured_nm, "
           "msy_predicted_nm, msz_predicted_nm, msy_residual_nm, msz_residual_nm (predicted - "
           "measured, validate's sign), ok, error (NaN predictions where the model refuses a "
           "sample). columns, negate: as read_recording takes them.")
      .def("to_text", [](const Model& model) { return model_text(*model.file); },
           "The model as a model file (text format) that reads back to the same model.")
      .def("write",
           [](const Model& model, const std::filesystem::path& path) {
             analysis::write_file_atomically(path, model_text(*model.file), "path");
           },
           py::arg("path"), "Writes the model file (atomically).")
      .def("__repr__", [](const Model& model) { return "<gearcoupling.Model '" + model.file->name + "'>"; });
}

}  // namespace gc::python
