#include "core/coupling_frame.h"

#include <cmath>

namespace gc {

Eigen::Matrix2d double_prime_to_coupling(double pressure_angle_rad, double direction_rad) {
  const double psi = pressure_angle_rad + direction_rad;
  const double c = std::cos(psi);
  const double s = std::sin(psi);
  Eigen::Matrix2d rotation;
  rotation << c, s,
             -s, c;
  return rotation;
}

}  // namespace gc
