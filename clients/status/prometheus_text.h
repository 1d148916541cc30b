// The Prometheus text exposition format, version 0.0.4: metric families with their # HELP and
// # TYPE lines, then samples with escaped label values. What /metrics is written with.
#pragma once

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace gc::status {

using Labels = std::vector<std::pair<std::string_view, std::string>>;

class PrometheusText {
 public:
  /// Starts family `name` ("counter", "gauge", "summary"); samples follow.
  void family(std::string_view name, std::string_view type, std::string_view help);
  /// One sample `name{labels} value` (name may carry a suffix of the family, e.g. _count).
  void sample(std::string_view name, const Labels& labels, double value);
  const std::string& text() const { return text_; }

 private:
  std::string text_;
};

}  // namespace gc::status
