// Test-cell recordings as CSV (docs/recordings.md; tokenized by analysis/csv_fields.h): a header
// naming each column as <quantity>_<unit>, in any order, then one sample per line. Units (any
// case: knm, kNm, KNM) are converted to SI on reading. Required: time, torque, misalignment,
// direction, msy, msz. Optional: speed, temperature, applied_my, applied_mz, hub_motion. Columns
// of no known quantity (a DAQ export's other channels) are ignored and listed; a rename map
// (--columns msy_nm=Ch3_kNm) reads a column the file names otherwise.
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

#include "analysis/csv_fields.h"
#include "analysis/csv_line_reader.h"
#include "analysis/derived_inputs.h"
#include "analysis/plain_csv_row.h"
#include "diagnosis/parallel_for.h"
#include "core/loading_direction.h"
#include "core/recorded_sample.h"

namespace gc::analysis {

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

/// How a recording reads a column name, for the other CSV readers (batch): the quantity that
/// `name` (<quantity>_<unit>) names, with `unit` set to the rest; nullopt when it names none.
std::optional<Quantity> column_quantity(std::string_view name, std::string_view& unit);
/// The quantity's spelling of `unit`, matched in any case ("kNm"), or nullopt.
std::optional<UnitSpelling> find_unit_spelling(Quantity quantity, std::string_view unit);
/// The column names the quantity accepts: "torque_nm, torque_knm, torque_mnm".
std::string column_spellings(Quantity quantity);

/// A column of the header: which quantity, in which unit.
struct RecordingColumn {
  Quantity quantity;
  std::string name;        ///< as written in the header
  UnitSpelling unit;
  std::size_t index = 0;   ///< its place among the file's fields, 0-based
};

/// A column the file names otherwise: `name` as docs/recordings.md spells it (e.g. "msy_knm")
/// for the file's column `header` (e.g. "Ch3_kNm").
struct ColumnRename {
  std::string name;
  std::string header;
};

/// "msy_knm=Ch3_kNm,torque_nm=T1" as renames. Throws FormatError naming the item that is not
/// name=header, or a name that is no column of docs/recordings.md.
std::vector<ColumnRename> parse_column_renames(std::string_view text);

/// What a header holds: the columns read, and those ignored.
struct RecordingHeader {
  std::vector<RecordingColumn> columns;
  std::vector<std::string> ignored;   ///< columns of no known quantity, as written
  std::size_t field_count = 0;        ///< every row has this many fields
};

/// How a pass reads a plain row (analysis/plain_csv_row.h): each field's use, and how many
/// are converted.
struct PlainCells {
  std::vector<CellUse> uses;
  std::size_t converted = 0;
};

/// What a recording is read with.
struct RecordingOptions {
  LoadingDirectionOptions loading;
  std::vector<ColumnRename> renames;
  /// Quantities read with their sign flipped (--negate torque: a dyno that logs the drive
  /// torque negative; the model takes the torque's magnitude).
  std::vector<Quantity> negated = {};
  /// What errors call the recording, "" for the file's name: "<DataFrame>" where the file is a
  /// scratch copy the user never named (Python).
  std::string source_name = {};
  /// Threads that parse a batch of rows at once (0: every hardware thread). Parsing is half of
  /// validate's work; the order-dependent checks (time going back, derived inputs) stay in file
  /// order, so what is read does not depend on it.
  unsigned threads = 1;
};

/// "torque,msy" as quantities (their header names, docs/recordings.md). Throws FormatError
/// naming an item that is no quantity.
std::vector<Quantity> parse_negated_quantities(std::string_view text);

/// A row excluded from the recording, and why.
struct RowProblem {
  long line = 0;           ///< 1-based line in the file (the header is line 1)
  int column = 0;          ///< 1-based column; 0 when the row as a whole is wrong
  std::string column_name;
  std::string message;
};

/// Parses the header line. Throws gc::InvalidInput naming "recording.<column>" (with
/// source:1:column) for an unknown unit of a known quantity, a quantity given twice, a required
/// quantity missing, or "recording.columns" for a rename whose header the file lacks.
RecordingHeader parse_recording_header(std::string_view header, std::string_view source_name,
                                       const std::vector<ColumnRename>& renames = {});

class RecordingReader {
 public:
  /// Opens `path`, reads its header (errors as parse_recording_header, or "recording" when
  /// the file cannot be read twice or is empty) and the misalignment of every good row, for the
  /// loading directions' dead band (loading_dead_band_rad, core/loading_direction.h).
  explicit RecordingReader(const std::filesystem::path& path, LoadingDirectionOptions loading = {});
  RecordingReader(const std::filesystem::path& path, const RecordingOptions& options);

  /// Reads up to `max_samples` good samples into `samples` (cleared first). Returns false
  /// when the file had no more rows.
  bool next_chunk(std::vector<RecordedSample>& samples, std::size_t max_samples);

  const std::vector<RecordingColumn>& columns() const { return header_.columns; }
  /// Columns of no known quantity, as written: not read.
  const std::vector<std::string>& ignored_columns() const { return header_.ignored; }
  std::size_t rows_read() const { return rows_read_; }          ///< data rows, good and bad
  std::size_t excluded_rows() const { return excluded_rows_; }
  /// The loading directions' dead band for this recording [rad].
  double loading_dead_band_rad() const { return loading_dead_band_rad_; }
  /// The first `kKeptProblems` problems; excluded_rows() counts them all.
  const std::vector<RowProblem>& problems() const { return problems_; }
  static constexpr std::size_t kKeptProblems = 1000;

 private:
  /// The values a pass over the rows needs: every one, or the dead band's (time and
  /// misalignment, and the quantities with a range limit); the other cells of that pass need
  /// only be known good, which most are at a glance (plainly_moderate_number).
  enum class Values { all, dead_band };
  /// A row's cells, without the checks that depend on the rows before it: safe to run on
  /// several rows at once, each thread with its own `fields`. The same problems whatever `values`.
  std::optional<RowProblem> parse_cells(std::string_view line, long line_number, CsvFields& fields,
                                        RecordedSample& sample, Values values) const;
  /// parse_cells' common case in one walk over the line (read_plain_row): false, with `sample`
  /// undefined, when the row is not plain or a value is not accepted in SI; parse_cells then
  /// reads it the general way and words its problem.
  bool read_plain_cells(std::string_view line, RecordedSample& sample, Values values) const;
  /// Time going backwards against the last good row.
  std::optional<RowProblem> time_problem(const RecordedSample& sample, long line_number) const;
  /// Reads up to `max_rows` rows and parses their cells on the reader's threads into parsed_;
  /// returns how many were read.
  std::size_t read_rows(std::size_t max_rows, Values values);
  void exclude(RowProblem problem);
  /// The first pass: the dead band from the misalignment of the good rows, then back to the
  /// first row.
  double scan_dead_band(const LoadingDirectionOptions& loading);

  std::string source_name_;
  std::ifstream in_;
  CsvLineReader lines_;
  RecordingHeader header_;
  PlainCells plain_all_, plain_dead_band_;   // each pass's plain walk (parse_cells)
  double loading_dead_band_rad_ = 0.0;
  std::optional<DerivedInputs> derived_;   // once the dead band is known
  struct ParsedRow {
    CsvLine line;
    RecordedSample sample;
    std::optional<RowProblem> problem;
  };
  ParallelFor parallel_for_;
  std::vector<ParsedRow> parsed_;     // one batch, its lines in lines_ until the next
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
  std::vector<std::string> ignored_columns;
};
Recording read_recording(const std::filesystem::path& path, LoadingDirectionOptions loading = {});
Recording read_recording(const std::filesystem::path& path, const RecordingOptions& options);

/// The CSV of `samples` with SI columns (time_s, torque_nm, misalignment_rad, direction_rad,
/// msy_nm, msz_nm, then the optional ones the first sample has), shortest round-trip numbers.
std::string recording_header(const RecordedSample& first);
void append_recording_row(std::string& out, const RecordedSample& sample);

}  // namespace gc::analysis
