// The CSV formats of `gearcoupling batch`.
//
// Input: CSV as analysis/csv_fields.h reads it (byte-order mark, CRLF, blank lines, quoted
// fields), a header line naming the columns, in any order, by the recordings' rules
// (analysis/recording_csv.h, docs/recordings.md: <quantity>_<unit>, the unit in any case):
//   torque_<nm|knm|mnm>, misalignment_<rad|deg|mrad>, mu   required
//   direction_<rad|deg|mrad>                              optional, 0 when absent
//   coupling                                              optional: a catalogue name or
//                                                         .textproto file per row (default: --coupling)
// then one load case per line. A field may be quoted ("1.5", "my, coupling.textproto").
//
// Output: one row per input row, in input order, under the header
//   line, coupling, q, teeth_in_contact, max_tooth_load_n, moment_y_nm, moment_z_nm,
//   sensor_moment_y_nm, sensor_moment_z_nm, magnitude_nm, contact_stress_pa,
//   bending_stress_pa, contact_safety_factor, bending_safety_factor, error
// `line` is the input line number (the header is line 1). A row that failed has its result
// fields empty and the reason in `error` (quoted); a good row has `error` empty. Numbers are
// the shortest text that reads back to the same double.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "analysis/csv_fields.h"
#include "analysis/load_case.h"
#include "core/model_error.h"
#include "core/operating_point.h"

namespace gc::analysis {

/// One input column: where it sits in a row (-1: absent), its name as written, and the factor to
/// SI (N·m, rad) of its unit.
struct BatchColumn {
  int index = -1;
  std::string name;
  double to_si = 1.0;
};

/// The input columns; direction and coupling may be absent.
struct BatchColumns {
  BatchColumn torque, misalignment, direction, mu, coupling;
  int count = 0;
};

/// `header` as next_csv_line returns it. Throws FormatError naming an unknown, repeated or
/// missing column, or an unknown unit of a known quantity with the accepted spellings.
BatchColumns parse_batch_header(std::string_view header);

/// One parsed input row; the raw fields are kept so errors can quote what the user wrote.
struct BatchRow {
  OperatingPoint point;
  std::string_view coupling;
  CsvFields fields;
};

/// Parses `line` into `row` (reusing its storage). Returns the reason when the row is not
/// well-formed: a quote left open, wrong field count, or a field that is not a number (naming the column).
std::optional<std::string> parse_batch_row(std::string_view line, const BatchColumns& columns,
                                           std::string_view default_coupling, BatchRow& row);

/// The core's complaint about a row, naming the column and the value as written; for a negative
/// torque, what to do (the model takes the torque's magnitude).
std::string describe_row_error(const InvalidInput& error, const BatchColumns& columns,
                               const BatchRow& row);

/// The output header line, ending in '\n'.
std::string batch_output_header();

void append_result_row(std::string& out, long line, std::string_view coupling,
                       const LoadCase& result);
void append_error_row(std::string& out, long line, std::string_view coupling,
                      std::string_view reason);

}  // namespace gc::analysis
