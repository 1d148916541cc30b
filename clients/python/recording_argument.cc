#include "clients/python/recording_argument.h"

#include <atomic>
#include <cstdint>

#include <unistd.h>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>
#include <pybind11/stl/filesystem.h>

#include "analysis/format_error.h"
#include "clients/python/bindings.h"
#include "clients/python/typed_objects.h"
#include "core/model_error.h"

namespace py = pybind11;

namespace gc::python {

ScratchFile::~ScratchFile() {
  std::error_code ignored;
  std::filesystem::remove(path, ignored);
}

namespace {

/// "a, b": the Python repr of each of `items`, for messages.
std::string reprs(py::handle items) {
  std::string text;
  for (py::handle item : items) text += (text.empty() ? "" : ", ") + py::repr(item).cast<std::string>();
  return text;
}

/// `text` as one CSV field: quoted, its quotes doubled, so a header may hold ','.
std::string csv_field(const std::string& text) {
  std::string quoted = "\"";
  for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
  return quoted + "\"";
}

std::vector<analysis::ColumnRename> renames_argument(py::handle columns) {
  if (columns.is_none()) return {};
  if (py::isinstance<py::str>(columns)) return analysis::parse_column_renames(columns.cast<std::string>());
  if (!py::isinstance<py::dict>(columns)) {
    throw InvalidInput("columns", "must be 'name=header,...' or a dict {name: header}, not " +
                                      py::repr(py::type::of(columns)).cast<std::string>());
  }
  // {name: header}, our column name to the user's header: checked one by one, as --columns
  // checks each item, so the error names the key the user wrote.
  std::vector<analysis::ColumnRename> renames;
  for (auto [name, header] : columns.cast<py::dict>()) {
    if (!py::isinstance<py::str>(name) || !py::isinstance<py::str>(header)) {
      throw InvalidInput("columns", "{" + reprs(py::make_tuple(name)) + ": " +
                                        reprs(py::make_tuple(header)) +
                                        "}: keys and values must be strings (name: header)");
    }
    try {
      const auto one = analysis::parse_column_renames(
          csv_field(name.cast<std::string>() + "=" + header.cast<std::string>()));
      renames.insert(renames.end(), one.begin(), one.end());
    } catch (const analysis::FormatError& error) {
      // "--columns 'x=y': 'x=y' is not name=header with a name of ... (one of: ...)" in the
      // dict's terms: the key is what is wrong.
      const std::string said = error.what();
      const std::size_t names = said.find("(one of:");
      throw InvalidInput("columns", "key " + reprs(py::make_tuple(name)) +
                                        " is not a column name of docs/recordings.md " +
                                        (names == std::string::npos ? std::string() : said.substr(names)));
    }
  }
  return renames;
}

std::vector<analysis::Quantity> negated_argument(py::handle negate) {
  if (negate.is_none()) return {};
  if (py::isinstance<py::str>(negate)) return analysis::parse_negated_quantities(negate.cast<std::string>());
  if (!py::isinstance<py::list>(negate) && !py::isinstance<py::tuple>(negate)) {
    throw InvalidInput("negate", "must be 'torque,msy' or a list ['torque', 'msy'], not " +
                                     py::repr(py::type::of(negate)).cast<std::string>());
  }
  std::string text;
  for (py::handle item : negate) {
    if (!py::isinstance<py::str>(item)) {
      throw InvalidInput("negate", "[" + reprs(negate) + "]: every item must be a quantity's name");
    }
    text += (text.empty() ? "" : ",") + csv_field(item.cast<std::string>());
  }
  return analysis::parse_negated_quantities(text);
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

}  // namespace

Recording recording_source(py::handle argument, const ColumnsArgument& columns,
                           const NegateArgument& negate) {
  if (py::isinstance<Recording>(argument)) return argument.cast<Recording>();
  Recording recording;
  recording.renames = renames_argument(columns);
  recording.negated = negated_argument(negate);
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

Recording read_recording(py::handle argument, const ColumnsArgument& columns,
                         const NegateArgument& negate) {
  Recording recording = recording_source(argument, columns, negate);
  if (!recording.data) {
    const analysis::RecordingOptions options{{}, recording.renames, recording.negated,
                                             recording.source_name()};
    py::gil_scoped_release release;
    recording.data = std::make_shared<const analysis::Recording>(
        analysis::read_recording(recording.path, options));
  }
  return recording;
}

void bind_recordings(py::module_& m) {
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

  m.def("read_recording",
        [](const RecordingArgument& source, const ColumnsArgument& columns,
           const NegateArgument& negate) { return read_recording(source, columns, negate); },
        py::arg("source"), py::kw_only(),
        py::arg("columns") = py::none(), py::arg("negate") = py::none(),
        "Reads a recording: a CSV file (docs/recordings.md) or a pandas DataFrame with its columns "
        "(<quantity>_<unit>, e.g. torque_nm, misalignment_deg, msy_knm). columns: renames as "
        "validate --columns takes them ('msy_knm=Ch3_kNm,...') or a dict {'msy_knm': 'Ch3_kNm'}. "
        "negate: quantities read with their sign flipped, as validate --negate ('torque' or "
        "['torque', 'msy']). Errors in a DataFrame name it '<DataFrame>' (line 1 its header, "
        "line N its row N - 2 by position).");
}

}  // namespace gc::python
