// Model against measurement from Python: models (bundled, a file or a dict; an effect added;
// written out), recordings (a CSV or a pandas DataFrame with the recording's columns), validate
// and diagnose with results as the CLI's --json (analysis/model_validation.h,
// analysis/model_diagnosis.h: the CLI's own code).
#include <atomic>
#include <filesystem>
#include <memory>
#include <optional>
#include <thread>

#include <unistd.h>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "analysis/atomic_file.h"
#include "analysis/effect_spec.h"
#include "analysis/model_diagnosis.h"
#include "analysis/model_validation.h"
#include "analysis/recording_csv.h"
#include "analysis/validation_report_html.h"
#include "analysis/validation_result.h"
#include "clients/cli/coupling_reference.h"
#include "clients/python/bindings.h"
#include "clients/python/result_object.h"
#include "codec/bundled_data.h"
#include "codec/coupling_catalog.h"
#include "codec/model_file.h"
#include "core/model_error.h"
#include "parallel/thread_parallel_for.h"

namespace py = pybind11;

namespace gc::python {
namespace {

// ---- models -----------------------------------------------------------------------------------

/// gearcoupling.Model: a model configuration with its coupling and effects, immutable.
struct Model {
  std::shared_ptr<const codec::ModelFile> file;
};

Model model_argument(py::handle argument) {
  if (py::isinstance<Model>(argument)) return argument.cast<Model>();
  const std::filesystem::path catalog = codec::default_catalog_dir();
  if (py::isinstance<py::dict>(argument)) {
    const std::string json = py::str(py::module_::import("json").attr("dumps")(argument));
    return {std::make_shared<const codec::ModelFile>(
        codec::parse_model_json(json, "model dict", catalog, std::filesystem::current_path()))};
  }
  std::filesystem::path path;
  if (py::isinstance<py::str>(argument) && !cli::is_file_reference(argument.cast<std::string>())) {
    path = codec::default_models_dir() / (argument.cast<std::string>() + ".textproto");
  } else {
    path = argument.cast<std::filesystem::path>();
  }
  return {std::make_shared<const codec::ModelFile>(codec::load_model_description(path, catalog))};
}

std::string model_text(const codec::ModelFile& file) {
  return codec::write_model_text(file.name, file.description, file.coupling, file.model);
}

Model with_effect(const Model& model, const std::string& spec) {
  codec::ModelFile file = *model.file;
  file.model = file.model.with_effect(analysis::parse_effect_spec(spec));
  return {std::make_shared<const codec::ModelFile>(std::move(file))};
}

// ---- recordings -------------------------------------------------------------------------------

/// A file removed when the last Recording reading it is gone: a DataFrame written as CSV.
struct ScratchFile {
  std::filesystem::path path;
  ~ScratchFile() {
    std::error_code ignored;
    std::filesystem::remove(path, ignored);
  }
};

/// gearcoupling.Recording: a recording read whole, with the file it came from.
struct Recording {
  std::filesystem::path path;       ///< what the readers read
  std::string source;               ///< its name in results: the path, or "<DataFrame>"
  std::shared_ptr<ScratchFile> scratch;
  std::shared_ptr<const analysis::Recording> data;
  std::vector<analysis::ColumnRename> renames;
};

std::vector<analysis::ColumnRename> renames_argument(const std::optional<std::string>& columns) {
  return columns ? analysis::parse_column_renames(*columns) : std::vector<analysis::ColumnRename>{};
}

// A DataFrame with the recording's columns as CSV: pandas prints floats so they read back
// exactly, and the one reader (units, malformed rows, loading directions) does the rest.
std::shared_ptr<ScratchFile> write_data_frame(py::handle frame) {
  static std::atomic<int> counter{0};
  auto scratch = std::make_shared<ScratchFile>();
  scratch->path = std::filesystem::temp_directory_path() /
                  ("gearcoupling-recording-" + std::to_string(getpid()) + "-" +
                   std::to_string(counter++) + ".csv");
  frame.attr("to_csv")(scratch->path.string(), py::arg("index") = false);
  return scratch;
}

Recording recording_source(py::handle argument, const std::optional<std::string>& columns) {
  if (py::isinstance<Recording>(argument)) return argument.cast<Recording>();
  Recording recording;
  recording.renames = renames_argument(columns);
  if (py::hasattr(argument, "to_csv") && py::hasattr(argument, "columns")) {
    recording.scratch = write_data_frame(argument);
    recording.path = recording.scratch->path;
    recording.source = "<DataFrame>";
  } else {
    recording.path = argument.cast<std::filesystem::path>();
    recording.source = recording.path.string();
  }
  return recording;
}

Recording read_recording(py::handle argument, const std::optional<std::string>& columns) {
  Recording recording = recording_source(argument, columns);
  if (!recording.data) {
    py::gil_scoped_release release;
    recording.data = std::make_shared<const analysis::Recording>(
        analysis::read_recording(recording.path, analysis::RecordingOptions{{}, recording.renames}));
  }
  return recording;
}

py::dict recording_arrays(const Recording& recording) {
  const auto& samples = recording.data->samples;
  const auto n = static_cast<py::ssize_t>(samples.size());
  py::array_t<double> time(n), torque(n), misalignment(n), direction(n), msy(n), msz(n);
  py::array_t<std::int32_t> loading(n);
  for (py::ssize_t i = 0; i < n; ++i) {
    const RecordedSample& s = samples[static_cast<std::size_t>(i)];
    time.mutable_at(i) = s.input.time_s;
    torque.mutable_at(i) = s.input.torque_nm;
    misalignment.mutable_at(i) = s.input.misalignment_rad;
    direction.mutable_at(i) = s.input.direction_rad;
    loading.mutable_at(i) = s.input.loading_direction;
    msy.mutable_at(i) = s.measured.y_nm;
    msz.mutable_at(i) = s.measured.z_nm;
  }
  py::dict out;
  out["time_s"] = time;
  out["torque_nm"] = torque;
  out["misalignment_rad"] = misalignment;
  out["direction_rad"] = direction;
  out["loading_direction"] = loading;
  out["msy_nm"] = msy;
  out["msz_nm"] = msz;
  return out;
}

py::list recording_problems(const Recording& recording) {
  py::list problems;
  for (const analysis::RowProblem& p : recording.data->problems) {
    py::dict problem;
    problem["line"] = p.line;
    problem["column"] = p.column;
    problem["column_name"] = p.column_name;
    problem["message"] = p.message;
    problems.append(problem);
  }
  return problems;
}

unsigned threads_argument(unsigned threads) {
  return threads == 0 ? std::max(1u, std::thread::hardware_concurrency()) : threads;
}

// ---- validate and diagnose --------------------------------------------------------------------

py::object validate(py::handle recording_argument, py::handle model_argument_, const std::string& add,
                    double reference_torque_nm, unsigned threads,
                    const std::optional<std::string>& columns,
                    const std::optional<std::filesystem::path>& html) {
  const Recording recording = recording_source(recording_argument, columns);
  const Model model = model_argument(model_argument_);
  std::unique_ptr<analysis::ModelValidation> validation;
  {
    py::gil_scoped_release release;
    validation = analysis::validate_model(
        recording.path, *model.file, add, reference_torque_nm,
        {static_cast<int>(threads_argument(threads)), 1u << 15, recording.renames});
    if (recording.scratch) validation->result.set_recording(recording.source);  // not the scratch file
    analysis::require_compared_samples(validation->result);
    if (html) {
      analysis::write_validation_report(*html, analysis::validation_report(validation->result, validation->runs));
    }
  }
  return result_object("ValidationResult", validation->result);
}

py::object diagnose(py::handle recording_argument, py::handle model_argument_,
                    const std::optional<std::filesystem::path>& write_model, unsigned threads,
                    const std::optional<std::string>& columns) {
  const Recording recording = read_recording(recording_argument, columns);
  const Model model = model_argument(model_argument_);
  const codec::ModelFile& file = *model.file;
  const analysis::Recording& data = *recording.data;
  std::optional<Diagnosis> diagnosis;
  gearcoupling::v1::DiagnosisResult result;
  std::optional<codec::ModelFile> diagnosed;
  {
    py::gil_scoped_release release;
    const analysis::RecordingCheck check = analysis::check_recording(file.model, file.name, data.samples);
    analysis::require_compared_samples(recording.source, file.name, check.compared, data.rows_read,
                                       data.excluded_rows, data.samples.size(), check.first_refusal);
    diagnosis.emplace(gc::diagnose(file.model, data.samples, thread_parallel_for(threads_argument(threads))));
    result = analysis::diagnosis_result(*diagnosis, recording.source, file.name, check, data);
    diagnosed.emplace(analysis::diagnosed_model(file, *diagnosis));
    if (write_model) {
      analysis::write_file_atomically(*write_model, model_text(*diagnosed), "write_model");
      result.set_written_model(write_model->string());
    }
  }
  py::object out = result_object("DiagnosisResult", result);
  out.attr("model") = Model{std::make_shared<const codec::ModelFile>(std::move(*diagnosed))};
  return out;
}

}  // namespace

void bind_measurement(py::module_& m) {
  py::class_<Model>(m, "Model",
                    "A model: a coupling and the effects of the library in order (idl/model_config.proto).")
      .def(py::init(&model_argument), py::arg("source"),
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
      .def("to_text", [](const Model& model) { return model_text(*model.file); },
           "The model as a model file (text format) that reads back to the same model.")
      .def("write",
           [](const Model& model, const std::filesystem::path& path) {
             analysis::write_file_atomically(path, model_text(*model.file), "path");
           },
           py::arg("path"), "Writes the model file (atomically).")
      .def("__repr__", [](const Model& model) { return "<gearcoupling.Model '" + model.file->name + "'>"; });

  py::class_<Recording>(m, "Recording",
                        "A test-cell recording read whole (docs/recordings.md), with its excluded rows.")
      .def_property_readonly("source", [](const Recording& r) { return r.source; })
      .def_property_readonly("rows_read", [](const Recording& r) { return r.data->rows_read; },
                             "Data rows in the file, good and bad.")
      .def_property_readonly("excluded_rows", [](const Recording& r) { return r.data->excluded_rows; },
                             "Malformed rows excluded (never dropped silently: see problems).")
      .def_property_readonly("problems", &recording_problems,
                             "The first 1000 excluded rows: line, column, column_name, message.")
      .def_property_readonly("ignored_columns", [](const Recording& r) { return r.data->ignored_columns; })
      .def("to_arrays", &recording_arrays,
           "The samples kept, in SI: time_s, torque_nm, misalignment_rad, direction_rad, "
           "loading_direction (+1 rising, -1 falling, 0 still), msy_nm, msz_nm.")
      .def("__len__", [](const Recording& r) { return r.data->samples.size(); });

  m.def("bundled_data_dir", [](const std::string& kind) { return codec::bundled_data_dir(kind); },
        py::arg("kind"),
        "The bundled data's folder of `kind` ('couplings', 'models', 'recordings'): the installed "
        "share/gearcoupling/<kind>, or the source tree's data/<kind> for a build-tree module.");
  m.def("read_recording", &read_recording, py::arg("source"), py::kw_only(),
        py::arg("columns") = py::none(),
        "Reads a recording: a CSV file (docs/recordings.md) or a pandas DataFrame with its columns "
        "(<quantity>_<unit>, e.g. torque_nm, misalignment_deg, msy_knm). columns: renames as "
        "validate --columns takes them ('msy_knm=Ch3_kNm,...').");
  m.def("validate", &validate, py::arg("recording"), py::arg("model"), py::kw_only(),
        py::arg("add") = "", py::arg("reference_torque_nm") = 1.5e6, py::arg("threads") = 0u,
        py::arg("columns") = py::none(), py::arg("html") = py::none(),
        "gearcoupling validate: the recording (a file, a DataFrame or a Recording) against the model "
        "(a Model, a name, a file or a dict); with add, also the model with that effect. Returns a "
        "ValidationResult (.to_dict() is validate --json). html: also write the HTML report there.");
  m.def("diagnose", &diagnose, py::arg("recording"), py::arg("model"), py::kw_only(),
        py::arg("write_model") = py::none(), py::arg("threads") = 0u, py::arg("columns") = py::none(),
        "gearcoupling diagnose: which effects the model lacks. Returns a DiagnosisResult "
        "(.to_dict() is diagnose --json) whose .model is the model with the effects found; "
        "write_model: also write that model file there.");
}

}  // namespace gc::python
