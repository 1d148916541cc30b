// The record lines of a CSV stream, read in large blocks of bytes rather than a getline and a
// string per line: a recording of a million rows is read twice by validate, and the line by line
// reading ran on one thread beside cells parsed on all. The same lines, line numbers and rules
// as next_csv_line (analysis/csv_fields.h: record_text).
#pragma once

#include <cstddef>
#include <istream>
#include <memory>
#include <string>
#include <string_view>

namespace gc::analysis {

/// A record line's place in CsvLineReader::text(), and its 1-based physical line number.
struct CsvLine {
  std::size_t offset = 0;
  std::size_t size = 0;
  long line_number = 0;
};

class CsvLineReader {
 public:
  /// Reads `in` from its current position, as physical line `line_number` + 1 on.
  explicit CsvLineReader(std::istream& in, long line_number = 0);

  /// The next record line, or false at the end. Its text stays in text() until release().
  bool next(CsvLine& line);
  /// The text of the lines handed out since the last release(); may move when next() reads
  /// more, so a line is looked up through its offset.
  std::string_view text() const { return {buffer_.get(), size_}; }
  std::string_view line_text(const CsvLine& line) const { return text().substr(line.offset, line.size); }
  /// True once every line of the stream was handed out.
  bool at_end() const { return at_end_ && scanned_ == size_; }
  /// Lets the next next() reuse the text of the lines handed out so far.
  void release();
  /// The stream position of the first byte not yet handed out, and its physical line: where a
  /// later rewind() starts reading again.
  std::streamoff position() const { return buffer_position_ + static_cast<std::streamoff>(scanned_); }
  long line_number() const { return line_number_; }
  /// Reads on from `position` (of position()) as physical line `line_number` + 1. Returns
  /// false when the stream cannot seek (not a regular file).
  bool rewind(std::streamoff position, long line_number);

 private:
  /// Appends the next block of the stream to buffer_; false at its end.
  bool read_block();

  std::istream& in_;
  // Not a std::string: growing one zeroes the bytes a read then overwrites, 2 % of validate.
  std::unique_ptr<char[]> buffer_;
  std::size_t size_ = 0;       // bytes of buffer_ read
  std::size_t capacity_ = 0;
  std::streamoff buffer_position_ = 0;   // stream position of buffer_[0]
  std::size_t scanned_ = 0;              // buffer_[0, scanned_) is handed out
  long line_number_ = 0;
  bool at_end_ = false;
};

}  // namespace gc::analysis
