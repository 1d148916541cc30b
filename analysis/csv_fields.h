// The one CSV tokenizer of recordings and batch input (RFC 4180, one record per line), and RFC
// 4180 quoting on output.
//
// Lines: a UTF-8 byte-order mark before the first line is skipped (spreadsheets write one), a
// final '\r' is dropped (CRLF files), and blank lines (spacing, a trailing empty line) hold no
// record. Fields: split at commas; an unquoted field is trimmed of blanks; a field in double
// quotes keeps its commas and blanks, with "" for a quote. A quoted number ("1.5") is a number;
// "1,5" is a field holding a comma, not a number. A record does not span lines.
#pragma once

#include <istream>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace gc::analysis {

/// Reads the next line holding a record into `line`, without its line break. `line_number`
/// counts the physical lines read so far (0 before the first; the header is then line 1), blank
/// ones included, so errors can name the line a user sees in an editor. Returns false at the end.
bool next_csv_line(std::istream& in, std::string& line, long& line_number);

/// The record that physical line `line_number` (1-based) holds, by the rules above: without the
/// byte-order mark of line 1 and a final '\r'; empty when the line is blank. One place for them,
/// for next_csv_line and the block reader (analysis/csv_line_reader.h).
std::string_view record_text(std::string_view physical_line, long line_number);

/// The fields of one record. Views point into the line or into the splitter's own storage (for
/// fields whose quotes were undone): valid until the next split() or the splitter's end.
class CsvFields {
 public:
  /// Splits `line`. Returns why it is not a well-formed record (a quote left open, text after a
  /// closing quote), or nothing.
  std::optional<std::string> split(std::string_view line);
  const std::vector<std::string_view>& fields() const { return fields_; }
  std::size_t size() const { return fields_.size(); }
  std::string_view operator[](std::size_t i) const { return fields_[i]; }

 private:
  std::vector<std::string_view> fields_;
  std::string unquoted_;
};

/// RFC 4180: quote a field holding a comma, quote or line break; double its quotes.
void append_csv_field(std::string& out, std::string_view field);

}  // namespace gc::analysis
