// The p-quantile of a sample by nearest rank: the value at rank floor(p * n) of the sorted
// sample (the maximum for p = 1); NaN for an empty sample. For the figures of benchmarks and
// load tests (p50, p99, max).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace gc::bench {

inline double percentile(std::vector<double> values, double p) {
  if (values.empty()) return std::nan("");
  const auto rank = std::min(static_cast<std::size_t>(p * static_cast<double>(values.size())), values.size() - 1);
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(rank), values.end());
  return values[rank];
}

}  // namespace gc::bench
