// A test cell's recent samples for the monitor's diagnosis: at most `capacity` of them, spanning
// at least `span_s` of measurement time once the cell has run that long. When the window is full
// and spans less, it keeps every other sample and from then on takes every other one (the stride
// doubles), so a 10 kHz cell and a 100 Hz one both give the diagnosis a whole test sequence in
// bounded memory, at the cost of a counter per sample.
#pragma once

#include <cstddef>
#include <cstdint>
#include <deque>
#include <vector>

#include "core/recorded_sample.h"

namespace gc::live {

class SampleWindow {
 public:
  /// `capacity` >= 2 samples, `span_s` > 0 [s].
  SampleWindow(std::size_t capacity, double span_s);

  void add(const RecordedSample& sample);
  /// Forgets every sample and the stride (a new run: its time starts anywhere).
  void clear();

  std::vector<RecordedSample> samples() const { return {samples_.begin(), samples_.end()}; }
  std::size_t size() const { return samples_.size(); }
  std::uint64_t stride() const { return stride_; }
  /// Samples offered since the last clear (taken or skipped by the stride).
  std::uint64_t offered() const { return offered_; }

 private:
  double span() const;

  std::size_t capacity_;
  double span_s_;
  std::uint64_t stride_ = 1;
  std::uint64_t offered_ = 0;
  std::deque<RecordedSample> samples_;
};

}  // namespace gc::live
