// The common case of a recording's row read in one walk over its characters: every field
// unquoted, without blanks, its numbers read by std::from_chars where they lie. The general
// tokenizer (analysis/csv_fields.h) trims each field, keeps a view of it and converts it after;
// on a million rows that was a third of reading a recording. Anything unusual (a quote, a blank,
// an empty or non-numeric cell, a field too many or too few, NaN or inf) makes the walk give up,
// and the caller reads the row the general way: that way alone words a row's problem, so a bad
// row is reported exactly as before.
#pragma once

#include <cstddef>
#include <span>
#include <string_view>

namespace gc::analysis {

/// What the walk does with a field.
enum class CellUse : unsigned char {
  skip,      ///< a column not read: any unquoted text
  check,     ///< must be plainly a moderate number (plainly_moderate_number), not converted
  convert,   ///< must be a finite number, converted
};

/// Reads `record` (a record line: analysis/csv_fields.h's record_text) as exactly
/// `uses.size()` plain fields. The values of the `convert` fields go to `values`, in field
/// order (it holds one per convert field). False when the line is not plain as above: then
/// `values` tells nothing and the row must be read by the general tokenizer.
bool read_plain_row(std::string_view record, std::span<const CellUse> uses, std::span<double> values);

}  // namespace gc::analysis
