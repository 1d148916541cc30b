// The two frames of Section 4.3: the coupling frame (y', z') and the frame (y'', z'') whose z''
// axis passes through the most loaded tooth, rotated by psi = phi + beta about x'.
#pragma once

#include <Eigen/Core>

namespace gc {

/// Eqs 44-45: (M_y', M_z') = R(psi) (M_y'', M_z'') with
///   R(psi) = [ cos psi   sin psi ]
///            [ -sin psi  cos psi ],  psi = phi + beta.
/// Its transpose is the inverse, which eq 3 uses.
Eigen::Matrix2d double_prime_to_coupling(double pressure_angle_rad, double direction_rad);

}  // namespace gc
