// gearcoupling.Recording: a test-cell recording read whole by the one recording reader
// (analysis/recording_csv.h), from a CSV file or a pandas DataFrame with the recording's columns.
#pragma once

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>

#include "analysis/recording_csv.h"
#include "clients/python/typed_objects.h"

namespace gc::python {

/// A file removed when the last Recording reading it is gone: a DataFrame written as CSV.
struct ScratchFile {
  std::filesystem::path path;
  ~ScratchFile();
};

/// A recording and the file it came from (read whole only where `data` is set).
struct Recording {
  std::filesystem::path path;       ///< what the readers read
  std::string source;               ///< its name in results: the path, or "<DataFrame>"
  std::shared_ptr<ScratchFile> scratch;
  std::shared_ptr<const analysis::Recording> data;
  std::vector<analysis::ColumnRename> renames;
  std::vector<analysis::Quantity> negated;   ///< read with the sign flipped (--negate)

  /// What errors and results call it: "" for the file's own name, "<DataFrame>" for a scratch
  /// copy of a DataFrame (the user never named that file).
  std::string source_name() const { return scratch ? source : std::string(); }
};

/// A Recording as is; a path; or a DataFrame, written as CSV to a scratch file (pandas prints
/// floats so that they read back exactly). `columns`: renames as --columns takes them, or a dict
/// {name: header} (e.g. {"msy_knm": "Ch3 [kNm]"}); `negate`: quantities read with their sign
/// flipped, as --negate takes them, or a list. Throws InvalidInput naming "columns" or "negate".
Recording recording_source(pybind11::handle argument, const ColumnsArgument& columns,
                           const NegateArgument& negate);

/// recording_source, read whole (the GIL released while reading).
Recording read_recording(pybind11::handle argument, const ColumnsArgument& columns,
                         const NegateArgument& negate);

}  // namespace gc::python
