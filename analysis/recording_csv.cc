#include "analysis/recording_csv.h"

#include <cerrno>
#include <cstring>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <numbers>
#include <span>
#include <thread>

#include <fmt/format.h>

#include "analysis/csv_fields.h"
#include "analysis/format_error.h"
#include "analysis/number_text.h"
#include "analysis/plain_csv_row.h"
#include "core/model_error.h"
#include "parallel/chunked_parallel_for.h"

namespace gc::analysis {
namespace {

constexpr std::size_t kRequiredCount = 6;  // time .. msz, the first quantities of the enum
constexpr double kDegree = std::numbers::pi / 180.0;
// Rows read before their cells are parsed on the reader's threads. Each batch starts and joins
// them, and on a host busy with other work a join waits milliseconds for a thread that is not
// scheduled: with 8192 rows validate took 1.2x main's time there, with 32768 0.83-0.88x. About
// 10 MB of lines and samples.
constexpr std::size_t kRowsParsedAtOnce = 32768;

constexpr std::array<Quantity, kQuantityCount> kQuantities{
    Quantity::time,  Quantity::torque,      Quantity::misalignment, Quantity::direction,
    Quantity::msy,   Quantity::msz,         Quantity::speed,        Quantity::temperature,
    Quantity::applied_my, Quantity::applied_mz, Quantity::hub_motion};

const std::vector<UnitSpelling> kMomentUnits{{"nm", 1.0}, {"knm", 1e3}, {"mnm", 1e6}};
const std::vector<UnitSpelling> kAngleUnits{{"rad", 1.0}, {"deg", kDegree}, {"mrad", 1e-3}};

// "applied_my_knm" -> quantity applied_my, unit "knm": the longest quantity name that is a
// prefix followed by '_' wins, so "applied_my" is not read as a unit of "applied".
std::optional<Quantity> quantity_of(std::string_view column, std::string_view& unit) {
  std::optional<Quantity> found;
  std::size_t found_length = 0;
  for (Quantity quantity : kQuantities) {
    const std::string_view name = quantity_name(quantity);
    if (column.size() > name.size() + 1 && column.starts_with(name) &&
        column[name.size()] == '_' && name.size() > found_length) {
      found = quantity;
      found_length = name.size();
    }
  }
  if (found) unit = column.substr(found_length + 1);
  return found;
}

std::string spellings_text(Quantity quantity) {
  std::string text;
  for (const UnitSpelling& spelling : unit_spellings(quantity)) {
    text += fmt::format("{}{}_{}", text.empty() ? "" : ", ", quantity_name(quantity), spelling.unit);
  }
  return text;
}

std::string all_columns_text() {
  std::string text;
  for (Quantity quantity : kQuantities) text += (text.empty() ? "" : "; ") + spellings_text(quantity);
  return text;
}

// Column 0: the header as a whole (a missing column has no place).
[[noreturn]] void header_error(std::string_view source, int column, std::string_view name,
                               const std::string& message) {
  throw InvalidInput("recording." + std::string(name.empty() ? "header" : name),
                     column > 0 ? fmt::format("{}:1:{}: {}", source, column, message)
                                : fmt::format("{}:1: {}", source, message));
}

std::string lower_case(std::string_view text) {
  std::string lower(text);
  for (char& c : lower) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return lower;
}

// The column `name` (as docs/recordings.md spells it), or nothing when it names no quantity.
// Units match in any case ("kNm", "KNM"): the spellings are lower case.
std::optional<RecordingColumn> parse_column(std::string_view name, std::string_view source,
                                            int column) {
  std::string_view unit;
  const std::optional<Quantity> quantity = quantity_of(name, unit);
  if (!quantity) return std::nullopt;
  if (const std::optional<UnitSpelling> spelling = find_unit_spelling(*quantity, unit)) {
    return RecordingColumn{*quantity, std::string(name), *spelling};
  }
  header_error(source, column, name,
               fmt::format("unknown unit '{}' in column '{}' (accepted, in any case: {}; "
                           "--columns renames a column)", unit, name, spellings_text(*quantity)));
}

// The documented name the renames give the file's column `header`, or `header` itself.
std::string_view renamed(std::string_view header, const std::vector<ColumnRename>& renames) {
  for (const ColumnRename& rename : renames) {
    if (rename.header == header) return rename.name;
  }
  return header;
}

void require_renamed_columns_present(const CsvFields& names, const std::vector<ColumnRename>& renames,
                                     std::string_view source) {
  for (const ColumnRename& rename : renames) {
    if (std::find(names.fields().begin(), names.fields().end(), rename.header) == names.fields().end()) {
      throw InvalidInput("recording.columns",
                         fmt::format("{}:1: --columns {}={}: the header has no column '{}'", source,
                                     rename.name, rename.header, rename.header));
    }
  }
}

void set_value(Quantity quantity, double value, RecordedSample& s) {
  switch (quantity) {
    case Quantity::time: s.input.time_s = value; break;
    case Quantity::torque: s.input.torque_nm = value; break;
    case Quantity::misalignment: s.input.misalignment_rad = value; break;
    case Quantity::direction: s.input.direction_rad = value; break;
    case Quantity::msy: s.measured.y_nm = value; break;
    case Quantity::msz: s.measured.z_nm = value; break;
    case Quantity::speed: s.input.speed_rpm = value; break;
    case Quantity::temperature: s.input.temperature_c = value; break;
    case Quantity::applied_my: s.input.applied_moment_y_nm = value; break;
    case Quantity::applied_mz: s.input.applied_moment_z_nm = value; break;
    case Quantity::hub_motion: s.hub_motion_m = value; break;
  }
}

// Largest magnitude of a quantity in SI, where a larger one would make a derived input
// overflow: the rotation phase integrates speed over time (a speed of 1e308 rpm gave an
// infinite phase, found by fuzz/recording_csv_fuzzer). 1e9 s is 31 years of recording;
// 1e5 rpm is beyond any drivetrain. The others need only be finite in SI.
std::optional<double> si_limit(Quantity quantity) {
  switch (quantity) {
    case Quantity::time: return 1.0e9;
    case Quantity::speed: return 1.0e5;
    default: return std::nullopt;
  }
}

std::string_view si_unit(Quantity quantity) {
  switch (quantity) {
    case Quantity::time: return "s";
    case Quantity::torque: case Quantity::msy: case Quantity::msz:
    case Quantity::applied_my: case Quantity::applied_mz: return "N·m";
    case Quantity::misalignment: case Quantity::direction: return "rad";
    case Quantity::speed: return "rpm";
    case Quantity::temperature: return "deg C";
    case Quantity::hub_motion: return "m";
  }
  return "";
}

// A unit's scale can take a finite cell past the largest double (1e308 knm).
bool si_acceptable(Quantity quantity, double si) {
  const std::optional<double> limit = si_limit(quantity);
  return std::isfinite(si) && !(limit && std::abs(si) > *limit);
}

// Why a finite cell's value in SI is not accepted (si_acceptable), or nullopt.
std::optional<std::string> si_complaint(std::string_view cell, Quantity quantity, double si) {
  if (si_acceptable(quantity, si)) return std::nullopt;
  if (!std::isfinite(si)) {
    return fmt::format("'{}' is not a finite number in {}", cell, si_unit(quantity));
  }
  const std::optional<double> limit = si_limit(quantity);
  if (limit && std::abs(si) > *limit) {
    return fmt::format("'{}' is out of range: {:g} {}, allowed [-{:g}, {:g}] {}", cell, si,
                       si_unit(quantity), *limit, *limit, si_unit(quantity));
  }
  return std::nullopt;
}

// What the dead band's pass over the rows reads: the time (its order), the misalignment, and
// the quantities whose range is limited in SI (si_limit).
bool dead_band_value(Quantity quantity) {
  return quantity == Quantity::time || quantity == Quantity::misalignment || si_limit(quantity).has_value();
}

// What the plain walk over a row (analysis/plain_csv_row.h) does with each field: converts the
// columns read (on the dead band's pass only its values, the others checked at a glance as
// parse_cells does) and skips the columns of no known quantity.
PlainCells plain_cells(const RecordingHeader& header, bool dead_band_pass) {
  PlainCells cells{std::vector<CellUse>(header.field_count, CellUse::skip), 0};
  for (const RecordingColumn& column : header.columns) {
    const bool convert = !dead_band_pass || dead_band_value(column.quantity);
    cells.uses[column.index] = convert ? CellUse::convert : CellUse::check;
    cells.converted += convert ? 1 : 0;
  }
  return cells;
}

std::string_view cell_complaint(std::string_view cell) {
  if (cell.empty()) return "empty cell";
  return "not a number";
}

}  // namespace

std::optional<Quantity> column_quantity(std::string_view name, std::string_view& unit) {
  return quantity_of(name, unit);
}

std::optional<UnitSpelling> find_unit_spelling(Quantity quantity, std::string_view unit) {
  const std::string lower = lower_case(unit);
  for (const UnitSpelling& spelling : unit_spellings(quantity)) {
    if (spelling.unit == lower) return spelling;
  }
  return std::nullopt;
}

std::string column_spellings(Quantity quantity) { return spellings_text(quantity); }

std::string_view quantity_name(Quantity quantity) {
  static constexpr std::array<std::string_view, kQuantityCount> kNames{
      "time", "torque", "misalignment", "direction", "msy", "msz",
      "speed", "temperature", "applied_my", "applied_mz", "hub_motion"};
  return kNames[static_cast<std::size_t>(quantity)];
}

const std::vector<UnitSpelling>& unit_spellings(Quantity quantity) {
  static const std::vector<UnitSpelling> kTime{{"s", 1.0}, {"ms", 1e-3}};
  static const std::vector<UnitSpelling> kSpeed{{"rpm", 1.0}, {"rad_s", 60.0 / (2.0 * std::numbers::pi)}};
  // Temperature stays in deg C, as MeasurementSample holds it.
  static const std::vector<UnitSpelling> kTemperature{{"c", 1.0}, {"k", 1.0, -273.15}};
  static const std::vector<UnitSpelling> kLength{{"m", 1.0}, {"mm", 1e-3}, {"um", 1e-6}};
  switch (quantity) {
    case Quantity::time: return kTime;
    case Quantity::misalignment:
    case Quantity::direction: return kAngleUnits;
    case Quantity::speed: return kSpeed;
    case Quantity::temperature: return kTemperature;
    case Quantity::hub_motion: return kLength;
    default: return kMomentUnits;
  }
}

std::vector<ColumnRename> parse_column_renames(std::string_view text) {
  std::vector<ColumnRename> renames;
  CsvFields items;
  if (auto problem = items.split(text)) throw FormatError(fmt::format("--columns '{}': {}", text, *problem));
  for (std::string_view item : items.fields()) {
    const std::size_t equals = item.find('=');
    const std::string_view name = trim(item.substr(0, equals));
    std::string_view unit;
    if (equals == std::string_view::npos || trim(item.substr(equals + 1)).empty() ||
        !quantity_of(name, unit)) {
      throw FormatError(fmt::format("--columns '{}': '{}' is not name=header with a name of "
                                    "docs/recordings.md (one of: {})", text, item, all_columns_text()));
    }
    renames.push_back({std::string(name), std::string(trim(item.substr(equals + 1)))});
  }
  return renames;
}

std::vector<Quantity> parse_negated_quantities(std::string_view text) {
  std::vector<Quantity> quantities;
  CsvFields items;
  if (auto problem = items.split(text)) throw FormatError(fmt::format("--negate '{}': {}", text, *problem));
  for (std::string_view item : items.fields()) {
    const std::string_view name = trim(item);
    const auto found = std::find_if(kQuantities.begin(), kQuantities.end(),
                                    [&](Quantity q) { return quantity_name(q) == name; });
    if (found == kQuantities.end()) {
      std::string names;
      for (Quantity q : kQuantities) names += fmt::format("{}{}", names.empty() ? "" : ", ", quantity_name(q));
      throw FormatError(fmt::format("--negate '{}': '{}' is no quantity of docs/recordings.md "
                                    "(one of: {})", text, item, names));
    }
    quantities.push_back(*found);
  }
  return quantities;
}

RecordingHeader parse_recording_header(std::string_view header, std::string_view source_name,
                                       const std::vector<ColumnRename>& renames) {
  CsvFields names;
  if (auto problem = names.split(header)) header_error(source_name, 0, "header", *problem);
  require_renamed_columns_present(names, renames, source_name);
  RecordingHeader result;
  result.field_count = names.size();
  std::array<int, kQuantityCount> seen{};
  for (std::size_t i = 0; i < names.size(); ++i) {
    const int column = static_cast<int>(i) + 1;
    const std::string_view name = renamed(names[i], renames);
    std::optional<RecordingColumn> parsed = parse_column(name, source_name, column);
    if (!parsed) {
      result.ignored.emplace_back(names[i]);
      continue;
    }
    int& first = seen[static_cast<std::size_t>(parsed->quantity)];
    if (first != 0) {
      header_error(source_name, column, name,
                   fmt::format("column '{}' repeats {} (column {})", name,
                               quantity_name(parsed->quantity), first));
    }
    first = column;
    parsed->index = i;
    result.columns.push_back(std::move(*parsed));
  }
  for (std::size_t q = 0; q < kRequiredCount; ++q) {
    if (seen[q] == 0) {
      // A column named for the quantity without its unit ("msy") is there: say only the unit is
      // missing, not the column (issue 39).
      std::string hint;
      for (std::size_t i = 0; i < names.size(); ++i) {
        if (renamed(names[i], renames) == quantity_name(kQuantities[q])) {
          hint = fmt::format("; column {} '{}' has no unit: name it {}", i + 1, names[i],
                             spellings_text(kQuantities[q]));
        }
      }
      header_error(source_name, 0, quantity_name(kQuantities[q]),
                   fmt::format("required column {} missing (one of: {}){}",
                               quantity_name(kQuantities[q]), spellings_text(kQuantities[q]), hint));
    }
  }
  return result;
}

RecordingReader::RecordingReader(const std::filesystem::path& path,
                                 LoadingDirectionOptions loading)
    : RecordingReader(path, RecordingOptions{loading, {}}) {}

RecordingReader::RecordingReader(const std::filesystem::path& path, const RecordingOptions& options)
    : source_name_(options.source_name.empty() ? path.filename().string() : options.source_name),
      in_(path, std::ios::binary),
      lines_(in_) {
  if (!in_) {
    // The OS's reason: no such file, permission denied, a directory (issue 39).
    const int reason = errno;
    throw InvalidInput("recording", "cannot read recording " + path.string() + ": " +
                                        std::strerror(reason));
  }
  CsvLine header;
  if (!lines_.next(header)) {
    throw InvalidInput("recording.header", source_name_ + ":1: empty file, expected a header");
  }
  header_ = parse_recording_header(lines_.line_text(header), source_name_, options.renames);
  for (const Quantity quantity : options.negated) {
    const auto column = std::find_if(header_.columns.begin(), header_.columns.end(),
                                     [&](const RecordingColumn& c) { return c.quantity == quantity; });
    if (column == header_.columns.end()) {
      throw InvalidInput("recording.negate",
                         fmt::format("{}:1: --negate {}: the header has no {} column (one of: {})",
                                     source_name_, quantity_name(quantity), quantity_name(quantity),
                                     spellings_text(quantity)));
    }
    column->unit.scale = -column->unit.scale;   // value_SI = -(value * scale + offset)
    column->unit.offset = -column->unit.offset;
  }
  const unsigned threads = options.threads == 0 ? std::max(1u, std::thread::hardware_concurrency())
                                                : options.threads;
  parallel_for_ = chunked_parallel_for(threads);
  plain_all_ = plain_cells(header_, false);
  plain_dead_band_ = plain_cells(header_, true);
  loading_dead_band_rad_ = scan_dead_band(options.loading);
  derived_.emplace(loading_dead_band_rad_, options.loading.still_after_s);
}

double RecordingReader::scan_dead_band(const LoadingDirectionOptions& loading) {
  const std::streamoff first_row = lines_.position();
  const long header_line = lines_.line_number();
  std::vector<double> amplitudes;
  while (const std::size_t rows = read_rows(kRowsParsedAtOnce, Values::dead_band)) {
    for (std::size_t r = 0; r < rows; ++r) {
      const ParsedRow& row = parsed_[r];
      // Problems are reported on pass 2.
      if (row.problem || time_problem(row.sample, row.line.line_number)) continue;
      last_time_s_ = row.sample.input.time_s;
      amplitudes.push_back(row.sample.input.misalignment_rad);
    }
  }
  last_time_s_.reset();
  if (!lines_.rewind(first_row, header_line)) {
    throw InvalidInput("recording", source_name_ + ": cannot be read twice (not a regular file?)");
  }
  return gc::loading_dead_band_rad(amplitudes, loading);
}

std::optional<RowProblem> RecordingReader::parse_cells(std::string_view line, long line_number,
                                                       CsvFields& fields, RecordedSample& s,
                                                       Values values) const {
  if (read_plain_cells(line, s, values)) return std::nullopt;
  if (auto problem = fields.split(line)) return RowProblem{line_number, 0, "", std::move(*problem)};
  if (fields.size() != header_.field_count) {
    return RowProblem{line_number, 0, "",
                      fmt::format("{} fields, the header has {}", fields.size(), header_.field_count)};
  }
  s = RecordedSample{};
  for (const RecordingColumn& column : header_.columns) {
    const std::string_view cell = fields[column.index];
    if (values == Values::dead_band && !dead_band_value(column.quantity) && plainly_moderate_number(cell)) {
      continue;  // finite in SI whatever the unit (the largest scale, MN·m, is 1e6)
    }
    const std::optional<double> value = parse_double(cell);
    const int column_number = static_cast<int>(column.index) + 1;
    if (!value) {
      return RowProblem{line_number, column_number, column.name,
                        fmt::format("{} '{}'", cell_complaint(cell), cell)};
    }
    if (!std::isfinite(*value)) {
      return RowProblem{line_number, column_number, column.name,
                        fmt::format("'{}' is not a finite number", cell)};
    }
    const double si = *value * column.unit.scale + column.unit.offset;
    if (auto complaint = si_complaint(cell, column.quantity, si)) {
      return RowProblem{line_number, column_number, column.name, std::move(*complaint)};
    }
    set_value(column.quantity, si, s);
  }
  return std::nullopt;
}

bool RecordingReader::read_plain_cells(std::string_view line, RecordedSample& s, Values values) const {
  const PlainCells& plain = values == Values::all ? plain_all_ : plain_dead_band_;
  std::array<double, kQuantityCount> read;  // a quantity has one column at most
  if (!read_plain_row(line, plain.uses, std::span(read).first(plain.converted))) return false;
  s = RecordedSample{};
  std::size_t next = 0;
  for (const RecordingColumn& column : header_.columns) {  // in field order, as `read`
    if (plain.uses[column.index] != CellUse::convert) continue;
    const double si = read[next++] * column.unit.scale + column.unit.offset;
    if (!si_acceptable(column.quantity, si)) return false;  // parse_cells words why
    set_value(column.quantity, si, s);
  }
  return true;
}

std::optional<RowProblem> RecordingReader::time_problem(const RecordedSample& s, long line_number) const {
  if (last_time_s_ && s.input.time_s < *last_time_s_) {
    const auto time_column = std::find_if(header_.columns.begin(), header_.columns.end(),
                                          [](const auto& c) { return c.quantity == Quantity::time; });
    return RowProblem{line_number, static_cast<int>(time_column->index) + 1, time_column->name,
                      fmt::format("time goes backwards: {} s after {} s", s.input.time_s,
                                  *last_time_s_)};
  }
  return std::nullopt;
}

void RecordingReader::exclude(RowProblem problem) {
  ++excluded_rows_;
  if (problems_.size() < kKeptProblems) problems_.push_back(std::move(problem));
}

std::size_t RecordingReader::read_rows(std::size_t max_rows, Values values) {
  if (parsed_.size() < max_rows) parsed_.resize(max_rows);
  lines_.release();
  std::size_t rows = 0;
  while (rows < max_rows && lines_.next(parsed_[rows].line)) ++rows;
  parallel_for_(rows, [&](std::size_t begin, std::size_t end) {
    CsvFields fields;  // the views it hands out live until its next split
    for (std::size_t r = begin; r < end; ++r) {
      ParsedRow& row = parsed_[r];
      row.problem = parse_cells(lines_.line_text(row.line), row.line.line_number, fields, row.sample, values);
    }
  });
  return rows;
}

bool RecordingReader::next_chunk(std::vector<RecordedSample>& samples, std::size_t max_samples) {
  samples.clear();
  // Never more rows than the samples still wanted: the reader stops where one read row by row
  // would, so a caller reading a file's first rows reads no further.
  while (samples.size() < max_samples) {
    const std::size_t rows = read_rows(std::min(max_samples - samples.size(), kRowsParsedAtOnce), Values::all);
    if (rows == 0) break;
    for (std::size_t r = 0; r < rows; ++r) {
      ParsedRow& row = parsed_[r];
      ++rows_read_;
      if (!row.problem) row.problem = time_problem(row.sample, row.line.line_number);
      if (row.problem) {
        exclude(std::move(*row.problem));
        continue;
      }
      last_time_s_ = row.sample.input.time_s;
      derived_->next(row.sample.input);
      samples.push_back(row.sample);
    }
  }
  return !samples.empty() || !lines_.at_end();
}

Recording read_recording(const std::filesystem::path& path, LoadingDirectionOptions loading) {
  return read_recording(path, RecordingOptions{loading, {}});
}

Recording read_recording(const std::filesystem::path& path, const RecordingOptions& options) {
  RecordingReader reader(path, options);
  Recording recording;
  std::vector<RecordedSample> chunk;
  while (reader.next_chunk(chunk, 65536)) {
    recording.samples.insert(recording.samples.end(), chunk.begin(), chunk.end());
  }
  recording.problems = reader.problems();
  recording.rows_read = reader.rows_read();
  recording.excluded_rows = reader.excluded_rows();
  recording.ignored_columns = reader.ignored_columns();
  return recording;
}

std::string recording_header(const RecordedSample& first) {
  std::string header = "time_s,torque_nm,misalignment_rad,direction_rad,msy_nm,msz_nm";
  if (first.input.speed_rpm) header += ",speed_rpm";
  if (first.input.temperature_c) header += ",temperature_c";
  if (first.input.applied_moment_y_nm) header += ",applied_my_nm";
  if (first.input.applied_moment_z_nm) header += ",applied_mz_nm";
  if (first.hub_motion_m) header += ",hub_motion_m";
  return header + "\n";
}

void append_recording_row(std::string& out, const RecordedSample& s) {
  for (double value : {s.input.time_s, s.input.torque_nm, s.input.misalignment_rad,
                       s.input.direction_rad, s.measured.y_nm, s.measured.z_nm}) {
    append_number(out, value);
    out += ',';
  }
  for (const std::optional<double>& value :
       {s.input.speed_rpm, s.input.temperature_c, s.input.applied_moment_y_nm,
        s.input.applied_moment_z_nm, s.hub_motion_m}) {
    if (!value) continue;
    append_number(out, *value);
    out += ',';
  }
  out.back() = '\n';
}

}  // namespace gc::analysis
