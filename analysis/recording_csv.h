// Test-cell recordings as CSV (docs/recordings.md): a header naming each column as
// <quantity>_<unit>, in any order, then one sample per line. Units are converted to SI on
// reading. Required: time, torque, misalignment, direction, msy, msz. Optional: speed,
// temperature, applied_my, applied_mz, hub_motion.
//
// The reader streams: it holds one chunk of samples at a time. Malformed rows (wrong field
// count, an empty, non-numeric, NaN or infinite cell, time going backwards) are excluded and
// reported with their line and column, never dropped in silence. It derives each sample's
// loading direction from the misalignment amplitude of the rows it keeps, with a dead band from
// the whole recording's misalignment noise (so it reads the rows twice: once, on opening, for
// the noise, then chunk by chunk), the rates of misalignment and torque (core/input_rate.h), and,
// where there is a speed column, the rotation phase.
#pragma once

#include <cstddef>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/input_rate.h"
#include "core/loading_direction.h"
#include "core/recorded_sample.h"
#include "core/rotation_phase.h"

namespace gc::cli {

enum class Quantity {
  time, torque, misalignment, direction, msy, msz,                        // required
  speed, temperature, applied_my, applied_mz, hub_motion,                 // optional
};
constexpr std::size_t kQuantityCount = 11;

/// One accepted unit spelling: value_SI = value * scale + offset.
struct UnitSpelling {
  std::string_view unit;   ///< as written after the quantity, e.g. "knm"
  double scale;
  double offset = 0.0;
};

/// The quantity's name in headers ("time", "applied_my", ...).
std::string_view quantity_name(Quantity quantity);
/// The unit spellings a quantity accepts, the SI one first.
const std::vector<UnitSpelling>& unit_spellings(Quantity quantity);

/// A column of the header: which quantity, in which unit.
struct RecordingColumn {
  Quantity quantity;
  std::string name;        ///< as written in the header
  UnitSpelling unit;
};

/// A row excluded from the recording, and why.
struct RowProblem {
  long line = 0;           ///< 1-based line in the file (the header is line 1)
  int column = 0;          ///< 1-based column; 0 when the row as a whole is wrong
  std::string column_name;
  std::string message;
};

/// Parses the header line. Throws gc::InvalidInput naming "recording.<column>" (with
/// source:1:column) for an unknown column, an unknown unit, a column given twice, or a required
/// quantity missing.
std::vector<RecordingColumn> parse_recording_header(std::string_view header,
                                                    std::string_view source_name);

class RecordingReader {
 public:
  /// Opens `path`, reads its header (errors as parse_recording_header, or "recording" when
  /// the file cannot be read twice or is empty) and the misalignment of every good row, for the
  /// loading directions' dead band (loading_dead_band_rad, core/loading_direction.h).
  explicit RecordingReader(const std::filesystem::path& path, LoadingDirectionOptions loading = {});

  /// Reads up to `max_samples` good samples into `samples` (cleared first). Returns false
  /// when the file had no more rows.
  bool next_chunk(std::vector<RecordedSample>& samples, std::size_t max_samples);

  const std::vector<RecordingColumn>& columns() const { return columns_; }
  std::size_t rows_read() const { return rows_read_; }          ///< data rows, good and bad
  std::size_t excluded_rows() const { return excluded_rows_; }
  /// The loading directions' dead band for this recording [rad].
  double loading_dead_band_rad() const { return loading_dead_band_rad_; }
  /// The first `kKeptProblems` problems; excluded_rows() counts them all.
  const std::vector<RowProblem>& problems() const { return problems_; }
  static constexpr std::size_t kKeptProblems = 1000;

 private:
  std::optional<RowProblem> parse_row(std::string_view line, RecordedSample& sample);
  void exclude(RowProblem problem);
  /// The first pass: the dead band from the misalignment of the good rows, then back to the
  /// first row.
  double scan_dead_band(const LoadingDirectionOptions& loading);

  std::string source_name_;
  std::ifstream in_;
  std::vector<RecordingColumn> columns_;
  double loading_dead_band_rad_ = 0.0;
  LoadingDirectionTracker loading_;
  bool has_speed_ = false;
  RotationPhaseIntegrator phase_;
  InputRateTracker misalignment_rate_, torque_rate_;
  std::string line_;
  std::vector<std::string_view> fields_;
  long line_number_ = 1;
  std::size_t rows_read_ = 0;
  std::size_t excluded_rows_ = 0;
  std::optional<double> last_time_s_;
  std::vector<RowProblem> problems_;
};

/// A whole recording in memory (e.g. for fitting), with its excluded rows.
struct Recording {
  std::vector<RecordedSample> samples;
  std::vector<RowProblem> problems;   ///< the first RecordingReader::kKeptProblems
  std::size_t rows_read = 0;
  std::size_t excluded_rows = 0;
};
Recording read_recording(const std::filesystem::path& path, LoadingDirectionOptions loading = {});

/// The CSV of `samples` with SI columns (time_s, torque_nm, misalignment_rad, direction_rad,
/// msy_nm, msz_nm, then the optional ones the first sample has), shortest round-trip numbers.
std::string recording_header(const RecordedSample& first);
void append_recording_row(std::string& out, const RecordedSample& sample);

}  // namespace gc::cli
