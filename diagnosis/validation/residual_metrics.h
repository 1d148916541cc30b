// Error metrics of one bending-moment channel, model against measurement, accumulated one
// sample at a time in constant memory so that a recording of any length streams through.
// The error of a sample is predicted - measured: a positive bias means the model reads high.
#pragma once

#include <cstddef>
#include <optional>

namespace gc {

struct ErrorMetrics {
  std::size_t count = 0;
  double rmse_nm = 0.0;             ///< sqrt(mean(e^2)) [N·m]
  double bias_nm = 0.0;             ///< mean(e) [N·m]
  double error_std_nm = 0.0;        ///< standard deviation of e about its mean [N·m]
  double max_abs_error_nm = 0.0;    ///< max |e| [N·m]
  /// 1 - SSE / SST about the measured mean; absent when the measurement does not vary (or
  /// there are fewer than two samples), where R^2 is undefined.
  std::optional<double> r_squared;
};

/// Running sums for ErrorMetrics (Welford's updates for the means, so that a million samples of
/// 1e6 N·m keep their digits). Mergeable, e.g. per thread or per bin.
class ErrorAccumulator {
 public:
  void add(double measured_nm, double predicted_nm);
  void merge(const ErrorAccumulator& other);
  std::size_t count() const { return count_; }
  ErrorMetrics metrics() const;

 private:
  std::size_t count_ = 0;
  double error_mean_ = 0.0;
  double error_m2_ = 0.0;        // sum of squared deviations of e from its mean
  double measured_mean_ = 0.0;
  double measured_m2_ = 0.0;     // SST
  double max_abs_error_ = 0.0;
};

}  // namespace gc
