// Which fitted parameters the data determine. A parameter whose Jacobian column is (nearly)
// zero or (nearly) a combination of the other columns cannot be told apart from them on this
// data: friction's reference_torque_nm, which only enters as mu_low_torque * T_ref; a direction
// whose amplitude is zero.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>

namespace gc {

struct Unidentifiable {
  int parameter = -1;     ///< column index
  int partner = -1;       ///< the column it is most correlated with, -1 when its column is ~zero
  double correlation = 0; ///< |r| with the partner
};

/// A free column the data cannot determine, if any: one whose share not explained by the other
/// free columns is below 1e-4 (1 - R^2), or whose norm is under 1e-9 of the largest. Of several,
/// the one listed last: effects list their magnitudes first and the modifiers after (friction's
/// mu_low_torque before reference_torque_nm), so the magnitude is fitted and the modifier held.
std::optional<Unidentifiable> find_unidentifiable(const Eigen::MatrixXd& jacobian,
                                                  const std::vector<bool>& free);

}  // namespace gc
