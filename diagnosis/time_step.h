// The typical time between a recording's rows: the median of the gaps between successive distinct
// times (duplicated time stamps, which a DAQ writes now and then, are skipped). The grid of the
// periodogram (cycle_period.h) and the step of the delay scan (delay_estimate.h).
#pragma once

#include <algorithm>
#include <vector>

#include <Eigen/Dense>

namespace gc {

/// `t` in time order [s]; 0 when no two times differ.
inline double typical_time_step(const Eigen::VectorXd& t) {
  std::vector<double> gaps;
  for (Eigen::Index k = 1; k < t.size(); ++k) if (t(k) > t(k - 1)) gaps.push_back(t(k) - t(k - 1));
  if (gaps.empty()) return 0.0;
  std::nth_element(gaps.begin(), gaps.begin() + static_cast<std::ptrdiff_t>(gaps.size() / 2), gaps.end());
  return gaps[gaps.size() / 2];
}

}  // namespace gc
