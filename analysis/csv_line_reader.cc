#include "analysis/csv_line_reader.h"

#include "analysis/csv_fields.h"

namespace gc::analysis {
namespace {

// Large enough that a read costs little beside the memchr and parse of its lines.
constexpr std::size_t kBlockBytes = 1u << 20;

}  // namespace

CsvLineReader::CsvLineReader(std::istream& in, long line_number) : in_(in), line_number_(line_number) {
  const std::streamoff start = in_.tellg();
  buffer_position_ = start < 0 ? 0 : start;  // a pipe: rewind() fails anyway
}

bool CsvLineReader::read_block() {
  if (at_end_) return false;
  const std::size_t old_size = buffer_.size();
  buffer_.resize(old_size + kBlockBytes);
  in_.read(buffer_.data() + old_size, static_cast<std::streamsize>(kBlockBytes));
  const auto got = static_cast<std::size_t>(in_.gcount());
  buffer_.resize(old_size + got);
  at_end_ = got < kBlockBytes;
  return got > 0;
}

bool CsvLineReader::next(CsvLine& line) {
  for (;;) {
    std::size_t end = buffer_.find('\n', scanned_);
    if (end == std::string::npos) {
      if (read_block()) continue;
      if (scanned_ == buffer_.size()) return false;
      end = buffer_.size();  // a last line without a line break
    }
    const std::size_t start = scanned_;
    scanned_ = end == buffer_.size() ? end : end + 1;
    ++line_number_;
    const std::string_view record =
        record_text(std::string_view(buffer_).substr(start, end - start), line_number_);
    if (record.empty()) continue;
    line = {static_cast<std::size_t>(record.data() - buffer_.data()), record.size(), line_number_};
    return true;
  }
}

void CsvLineReader::release() {
  buffer_.erase(0, scanned_);  // moves only the part of a line read ahead
  buffer_position_ += static_cast<std::streamoff>(scanned_);
  scanned_ = 0;
}

bool CsvLineReader::rewind(std::streamoff position, long line_number) {
  in_.clear();
  if (!in_.seekg(position)) return false;
  buffer_.clear();
  buffer_position_ = position;
  scanned_ = 0;
  line_number_ = line_number;
  at_end_ = false;
  return true;
}

}  // namespace gc::analysis
