// Streams a recording through one or more models (validate; before/after comparisons): reads it
// in chunks (rows parsed on several threads), predicts each chunk on several threads
// (CouplingModel is reentrant; small pieces handed out as threads come free), and feeds the errors to
// one ValidationAccumulator and PointSampler per model, in file order, so the result does not
// depend on the thread count. A model whose effects read other samples than the one predicted
// (CouplingModel::input_reach) sees, at a chunk's edges, the rows of the chunks beside it, so the
// result does not depend on where the chunks fall either. Memory is bounded by the chunk size and
// that reach, whatever the recording's length.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "analysis/recording_csv.h"
#include "analysis/scale_check.h"
#include "core/coupling_model.h"
#include "diagnosis/validation/error_bins.h"
#include "diagnosis/validation/plot_points.h"

namespace gc::analysis {

struct ModelRun {
  std::string name;
  const CouplingModel* model;
  ValidationAccumulator validation;
  PointSampler points;
  MomentScale scale = {};   ///< measured against predicted RMS (analysis/scale_check.h)
};

struct RecordingSummary {
  std::string source;
  std::size_t rows_read = 0;
  std::size_t excluded_rows = 0;
  std::vector<RowProblem> problems;   ///< the first RecordingReader::kKeptProblems
  std::vector<std::string> ignored_columns;
  double largest_misalignment_rad = 0.0;   ///< of the rows read well, refused ones included
  double largest_torque_nm = 0.0;          ///< |T|, likewise
};

struct ValidationRunOptions {
  int threads = 1;
  std::size_t chunk_samples = 1u << 15;
  std::vector<ColumnRename> renames = {};   ///< --columns
  std::vector<Quantity> negated = {};       ///< --negate
  std::string source_name = {};             ///< RecordingOptions::source_name
};

/// Compares every model of `runs` with the recording at `path`. Samples a model refuses are
/// counted by the field its error names (ValidationAccumulator::reject), never dropped silently.
RecordingSummary run_validation(const std::filesystem::path& path, std::vector<ModelRun>& runs,
                                const ValidationRunOptions& options);

}  // namespace gc::analysis
