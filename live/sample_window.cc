#include "live/sample_window.h"

#include <algorithm>

#include "core/model_error.h"

namespace gc::live {

SampleWindow::SampleWindow(std::size_t capacity, double span_s)
    : capacity_(capacity), span_s_(span_s) {
  if (capacity < 2) {
    throw InvalidInput("diagnosis_samples", std::to_string(capacity) + " is out of range: allowed 2 or more");
  }
  if (!(span_s > 0.0)) {
    throw InvalidInput("diagnosis_window_s", std::to_string(span_s) + " is out of range: allowed > 0 s");
  }
}

double SampleWindow::span() const {
  return samples_.empty() ? 0.0 : samples_.back().input.time_s - samples_.front().input.time_s;
}

void SampleWindow::add(const RecordedSample& sample) {
  if (offered_++ % stride_ != 0) return;
  if (samples_.size() == capacity_) {
    if (span() < span_s_) {
      // Full before it spans span_s: thin to every other sample, and take every other from now.
      std::deque<RecordedSample> thinned;
      for (std::size_t i = 0; i < samples_.size(); i += 2) thinned.push_back(samples_[i]);
      samples_.swap(thinned);
      stride_ *= 2;
      offered_ = 1;   // this sample is the first of the new stride
    } else {
      samples_.pop_front();
    }
  }
  samples_.push_back(sample);
}

void SampleWindow::clear() {
  samples_.clear();
  stride_ = 1;
  offered_ = 0;
}

}  // namespace gc::live
