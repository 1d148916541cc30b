#include "diagnosis/validation/residual_metrics.h"

#include <algorithm>
#include <cmath>

namespace gc {
namespace {

// Chan et al.'s pairwise update of a mean and its sum of squared deviations.
void merge_moments(double& mean, double& m2, std::size_t count, double other_mean,
                   double other_m2, std::size_t other_count) {
  const double total = static_cast<double>(count + other_count);
  const double delta = other_mean - mean;
  mean += delta * static_cast<double>(other_count) / total;
  m2 += other_m2 + delta * delta * static_cast<double>(count) *
                       static_cast<double>(other_count) / total;
}

}  // namespace

void ErrorAccumulator::add(double measured_nm, double predicted_nm) {
  const double error = predicted_nm - measured_nm;
  ++count_;
  const double n = static_cast<double>(count_);
  const double error_delta = error - error_mean_;
  error_mean_ += error_delta / n;
  error_m2_ += error_delta * (error - error_mean_);
  const double measured_delta = measured_nm - measured_mean_;
  measured_mean_ += measured_delta / n;
  measured_m2_ += measured_delta * (measured_nm - measured_mean_);
  max_abs_error_ = std::max(max_abs_error_, std::abs(error));
}

void ErrorAccumulator::merge(const ErrorAccumulator& other) {
  if (other.count_ == 0) return;
  if (count_ == 0) {
    *this = other;
    return;
  }
  merge_moments(error_mean_, error_m2_, count_, other.error_mean_, other.error_m2_, other.count_);
  merge_moments(measured_mean_, measured_m2_, count_, other.measured_mean_, other.measured_m2_,
                other.count_);
  count_ += other.count_;
  max_abs_error_ = std::max(max_abs_error_, other.max_abs_error_);
}

ErrorMetrics ErrorAccumulator::metrics() const {
  ErrorMetrics m;
  m.count = count_;
  if (count_ == 0) return m;
  const double n = static_cast<double>(count_);
  const double sse = error_m2_ + n * error_mean_ * error_mean_;
  m.rmse_nm = std::sqrt(sse / n);
  m.bias_nm = error_mean_;
  m.error_std_nm = std::sqrt(error_m2_ / n);
  m.max_abs_error_nm = max_abs_error_;
  // Below a relative 1e-12 the measurement is constant to rounding: R^2 has no meaning.
  if (count_ > 1 && measured_m2_ > 1e-12 * n * (1.0 + measured_mean_ * measured_mean_)) {
    m.r_squared = 1.0 - sse / measured_m2_;
  }
  return m;
}

}  // namespace gc
