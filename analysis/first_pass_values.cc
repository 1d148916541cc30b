#include "analysis/first_pass_values.h"

namespace gc::analysis {

void FirstPassValues::add_good(double time_s, double misalignment_rad) {
  time_s_.push_back(time_s);
  misalignment_rad_.push_back(misalignment_rad);
  ++rows_;
}

void FirstPassValues::add_bad() { bad_rows_.push_back(rows_++); }

std::optional<std::size_t> FirstPassValues::next_row() {
  const std::size_t row = next_row_++;
  if (row >= rows_) return std::nullopt;
  if (next_bad_ < bad_rows_.size() && bad_rows_[next_bad_] == row) {
    ++next_bad_;
    return std::nullopt;
  }
  return next_good_++;
}

}  // namespace gc::analysis
