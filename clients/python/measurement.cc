// Model against measurement from Python: validate and diagnose a recording (recording_argument.h)
// against a model (model_argument.h), results as the CLI's --json: the CLI's own code
// (analysis/model_validation.h, analysis/model_diagnosis.h).
#include <filesystem>
#include <memory>
#include <optional>
#include <thread>

#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "analysis/atomic_file.h"
#include "analysis/model_diagnosis.h"
#include "analysis/model_validation.h"
#include "analysis/validation_report_html.h"
#include "analysis/validation_result.h"
#include "clients/python/bindings.h"
#include "clients/python/typed_objects.h"
#include "clients/python/model_argument.h"
#include "clients/python/predictions.h"
#include "clients/python/recording_argument.h"
#include "clients/python/result_object.h"
#include "codec/bundled_data.h"
#include "parallel/thread_parallel_for.h"

namespace py = pybind11;

namespace gc::python {
namespace {

unsigned threads_argument(unsigned threads) {
  return threads == 0 ? std::max(1u, std::thread::hardware_concurrency()) : threads;
}

ValidationResultObject validate(const RecordingArgument& recording_argument,
                                const ModelArgument& model_argument_, const std::string& add,
                    double reference_torque_nm, unsigned threads,
                    const ColumnsArgument& columns, const NegateArgument& negate,
                    const std::optional<std::filesystem::path>& html, bool force_scale) {
  const Recording recording = recording_source(recording_argument, columns, negate);
  const Model model = model_argument(model_argument_);
  std::unique_ptr<analysis::ModelValidation> validation;
  {
    py::gil_scoped_release release;
    validation = analysis::validate_model(
        recording.path, *model.file, add, reference_torque_nm,
        {static_cast<int>(threads_argument(threads)), 1u << 15, recording.renames,
         recording.negated, recording.source_name()});
    analysis::require_compared_samples(validation->result, analysis::UnitFix::python);
    // The CLI's unit check, worded by the same function: refused, not a warning in .warnings.
    if (!force_scale) {
      const analysis::ModelRun& run = validation->runs.front();
      analysis::refuse_unit_slip(recording.source, run.scale.refusal(run.name),
                                 analysis::UnitFix::python);
    }
    if (html) {
      analysis::write_validation_report(*html, analysis::validation_report(validation->result, validation->runs));
    }
  }
  py::object out = result_object("ValidationResult", validation->result);
  // For samples(): the recording as given (read again, whole, when asked) and the models.
  py::list models;
  models.append(py::cast(model));
  if (!add.empty()) models.append(py::cast(with_effect(model, add)));
  // The recording as read here (renames, negate, the DataFrame's scratch copy kept alive).
  out.attr("_sample_sources") = py::make_tuple(py::cast(recording), py::none(), models);
  return out;
}

/// The model as the user named it, as `diagnose --model` records it (DiagnosisResult.model_source):
/// a bundled name or a file's path as given; a Model object or a dict by the model's own name.
std::string model_source(const ModelArgument& argument, const codec::ModelFile& file) {
  if (py::isinstance<py::str>(argument)) return argument.cast<std::string>();
  if (py::hasattr(argument, "__fspath__")) return py::str(argument.attr("__fspath__")()).cast<std::string>();
  return file.name;
}

DiagnosisResultObject diagnose(const RecordingArgument& recording_argument,
                               const ModelArgument& model_argument_,
                    const std::optional<std::filesystem::path>& write_model, unsigned threads,
                    const ColumnsArgument& columns, const NegateArgument& negate,
                    bool force_scale) {
  const Recording recording = read_recording(recording_argument, columns, negate);
  const Model model = model_argument(model_argument_);
  const codec::ModelFile& file = *model.file;
  const analysis::Recording& data = *recording.data;
  std::optional<Diagnosis> diagnosis;
  gearcoupling::v1::DiagnosisResult result;
  std::optional<codec::ModelFile> diagnosed;
  const std::string source = model_source(model_argument_, file);
  {
    py::gil_scoped_release release;
    const analysis::RecordingCheck check = analysis::check_recording(file.model, file.name, data.samples);
    analysis::require_compared_samples(recording.source, file.name, check.compared, data.rows_read,
                                       data.excluded_rows, data.samples.size(), check.first_refusal,
                                       analysis::UnitFix::python);
    if (!force_scale) analysis::refuse_unit_slip(recording.source, check.refusal, analysis::UnitFix::python);
    diagnosis.emplace(gc::diagnose(file.model, data.samples, thread_parallel_for(threads_argument(threads))));
    result = analysis::diagnosis_result(*diagnosis, recording.source, file.name, check, data);
    result.set_model_source(source);
    diagnosed.emplace(analysis::diagnosed_model(file, *diagnosis));
    if (write_model) {
      analysis::write_file_atomically(*write_model, model_text(*diagnosed), "write_model");
      result.set_written_model(write_model->string());
    }
  }
  py::object out = result_object("DiagnosisResult", result);
  const Model found{std::make_shared<const codec::ModelFile>(std::move(*diagnosed))};
  out.attr("model") = found;
  py::list models;
  models.append(py::cast(model));
  models.append(py::cast(found));
  out.attr("_sample_sources") = py::make_tuple(py::cast(recording), py::none(), models);
  return out;
}

}  // namespace

void bind_measurement(py::module_& m) {
  m.def("bundled_data_dir", [](const std::string& kind) { return codec::bundled_data_dir(kind); },
        py::arg("kind"),
        "The bundled data's folder of `kind` ('couplings', 'models', 'recordings'): the installed "
        "share/gearcoupling/<kind>, or the source tree's data/<kind> for a build-tree module.");
  m.def("validate", &validate, py::arg("recording"), py::arg("model"), py::kw_only(),
        py::arg("add") = "", py::arg("reference_torque_nm") = 1.5e6, py::arg("threads") = 0u,
        py::arg("columns") = py::none(), py::arg("negate") = py::none(), py::arg("html") = py::none(),
        py::arg("force_scale") = false,
        "gearcoupling validate: the recording (a file, a DataFrame or a Recording) against the model "
        "(a Model, a name, a file or a dict); with add, also the model with that effect. Returns a "
        "ValidationResult (.to_dict() is validate --json; .samples(model=0) the per-sample "
        "predictions and residuals as a DataFrame, model 1 the one with the effect added). html: "
        "also write the HTML report there. A moment channel 1000 times the model's (kN·m under an _nm "
        "header) raises ValueError naming the unit error, as validate exits 2; force_scale=True runs "
        "anyway. columns and negate as read_recording takes them (validate --columns, --negate).");
  m.def("diagnose", &diagnose, py::arg("recording"), py::arg("model"), py::kw_only(),
        py::arg("write_model") = py::none(), py::arg("threads") = 0u, py::arg("columns") = py::none(),
        py::arg("negate") = py::none(), py::arg("force_scale") = false,
        "gearcoupling diagnose: which effects the model lacks. Returns a DiagnosisResult "
        "(.to_dict() is diagnose --json) whose .model is the model with the effects found and "
        ".samples(model=0) the per-sample predictions and residuals as a DataFrame (model 0 the "
        "model given, 1 the model found); write_model: also write that model file there. A unit slip "
        "raises ValueError as in validate; force_scale=True runs anyway. columns and negate as "
        "read_recording takes them (diagnose --columns, --negate).");
}

}  // namespace gc::python
