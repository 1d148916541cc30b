// What a recording's first pass (the dead band's) read of each good row, its time and
// misalignment, handed back to the second pass row by row so that those two cells are converted
// once: std::from_chars was a fifth of validate's work, and these were two of its eight numbers
// a row. The same rows are good on both passes (the same checks, analysis/recording_csv.h), so
// the k-th good row of one is the k-th of the other. Costs a double a good row beside the
// misalignments the dead band keeps anyway.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <vector>

namespace gc::analysis {

class FirstPassValues {
 public:
  /// The first pass's next row: good, with its values in SI, or bad.
  void add_good(double time_s, double misalignment_rad);
  void add_bad();

  /// The misalignments of the good rows, in file order.
  std::span<const double> misalignments() const { return misalignment_rad_; }

  /// For the second pass's next row: the index of its values (time_s(), misalignment_rad()),
  /// or nullopt for a row the first pass found bad or never saw.
  std::optional<std::size_t> next_row();
  double time_s(std::size_t index) const { return time_s_[index]; }
  double misalignment_rad(std::size_t index) const { return misalignment_rad_[index]; }

 private:
  std::vector<double> time_s_, misalignment_rad_;   // of the good rows
  std::vector<std::size_t> bad_rows_;               // the bad rows' places among all rows
  std::size_t rows_ = 0;                            // rows added
  std::size_t next_row_ = 0, next_good_ = 0, next_bad_ = 0;   // the second pass's
};

}  // namespace gc::analysis
