#include "diagnosis/start_points.h"

namespace gc {
namespace {

double radical_inverse(int index, int base) {
  double result = 0.0, fraction = 1.0 / base;
  for (; index > 0; index /= base, fraction /= base) result += fraction * (index % base);
  return result;
}

}  // namespace

std::vector<Eigen::VectorXd> halton_points(int dimensions, int count) {
  static constexpr int kPrimes[] = {2, 3, 5, 7, 11, 13, 17, 19, 23, 29, 31, 37};
  std::vector<Eigen::VectorXd> points;
  for (int k = 1; k <= count; ++k) {
    Eigen::VectorXd x(dimensions);
    for (int d = 0; d < dimensions; ++d) x(d) = radical_inverse(k, kPrimes[d % 12]);
    points.push_back(x);
  }
  return points;
}

}  // namespace gc
