#include "core/input_noise.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace gc {
namespace {

// Median of `values`, reordering them (nth_element: linear time on long recordings).
double median_of(std::vector<double>& values) {
  const std::size_t middle = values.size() / 2;
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(middle),
                   values.end());
  const double upper = values[middle];
  if (values.size() % 2 == 1) return upper;
  const double lower = *std::max_element(values.begin(),
                                         values.begin() + static_cast<std::ptrdiff_t>(middle));
  return 0.5 * (lower + upper);
}

}  // namespace

double input_noise_sigma(std::span<const double> series) {
  if (series.size() < 3) return 0.0;
  std::vector<double> second(series.size() - 2);
  for (std::size_t i = 1; i + 1 < series.size(); ++i) {
    second[i - 1] = series[i - 1] - 2.0 * series[i] + series[i + 1];
  }
  const double centre = median_of(second);
  for (double& d : second) d = std::abs(d - centre);
  // 1.4826 = 1 / Phi^-1(3/4): MAD to standard deviation for normal noise; sqrt(6) from
  // var(x_{i-1} - 2 x_i + x_{i+1}) = 6 sigma^2.
  return 1.4826 * median_of(second) / std::sqrt(6.0);
}

}  // namespace gc
