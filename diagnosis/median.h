// The median of a sample, as the diagnosis' robust scales and levels take it: the upper of the two
// middle values for an even count (nth_element at n / 2), so no two values are averaged.
#pragma once

#include <algorithm>
#include <cstddef>
#include <vector>

namespace gc {

/// The element at n / 2 of `values` in order; 0 for none. Taken by value: nth_element reorders.
inline double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

}  // namespace gc
