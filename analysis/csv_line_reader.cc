#include "analysis/csv_line_reader.h"

#include <algorithm>

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
  if (size_ + kBlockBytes > capacity_) {
    const std::size_t capacity = std::max(2 * capacity_, size_ + kBlockBytes);
    auto grown = std::make_unique_for_overwrite<char[]>(capacity);
    std::copy_n(buffer_.get(), size_, grown.get());
    buffer_ = std::move(grown);
    capacity_ = capacity;
  }
  in_.read(buffer_.get() + size_, static_cast<std::streamsize>(kBlockBytes));
  const auto got = static_cast<std::size_t>(in_.gcount());
  size_ += got;
  at_end_ = got < kBlockBytes;
  return got > 0;
}

bool CsvLineReader::next(CsvLine& line) {
  for (;;) {
    std::size_t end = text().find('\n', scanned_);
    if (end == std::string_view::npos) {
      if (read_block()) continue;
      if (scanned_ == size_) return false;
      end = size_;  // a last line without a line break
    }
    const std::size_t start = scanned_;
    scanned_ = end == size_ ? end : end + 1;
    ++line_number_;
    const std::string_view record = record_text(text().substr(start, end - start), line_number_);
    if (record.empty()) continue;
    line = {static_cast<std::size_t>(record.data() - buffer_.get()), record.size(), line_number_};
    return true;
  }
}

void CsvLineReader::release() {
  std::copy(buffer_.get() + scanned_, buffer_.get() + size_, buffer_.get());  // the part of a line read ahead
  size_ -= scanned_;
  buffer_position_ += static_cast<std::streamoff>(scanned_);
  scanned_ = 0;
}

bool CsvLineReader::rewind(std::streamoff position, long line_number) {
  in_.clear();
  if (!in_.seekg(position)) return false;
  size_ = 0;
  buffer_position_ = position;
  scanned_ = 0;
  line_number_ = line_number;
  at_end_ = false;
  return true;
}

}  // namespace gc::analysis
