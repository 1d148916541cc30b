// Contact and bending stress of a loaded coupling tooth and their safety factors. The paper
// promises them and defers to its reference [18]; the method here is stated in docs/model.md:
// - contact: Hertz line contact of a cylinder of radius R_F (the crown, in the lead direction)
//   on the conformal sleeve flank, over the active profile length h_w / cos(phi);
// - bending: Lewis/AGMA root stress sigma = W_t / (F_e m Y) with W_t = P_d cos(phi), the form
//   factor of the weaker member, and the root length that carries a load applied over the
//   eq 18 contact length F_c: spread at 45 deg down the tooth height h_t on either side,
//   F_e = min(F, F_c + 2 h_t), h_t = (D_o - D_root) / 2 (the load-dispersion rule for
//   concentrated loads on cantilever teeth).
#pragma once

namespace gc {

class CouplingGeometry;

struct ToothStress {
  double contact_stress_pa = 0.0;      ///< sigma_H, maximum Hertzian pressure [Pa]
  double contact_half_width_m = 0.0;   ///< Hertz half width in the lead direction [m]
  double bending_stress_pa = 0.0;      ///< sigma_F, root bending stress [Pa]
  double contact_safety_factor = 0.0;  ///< S_H = allowable / sigma_H [-]
  double bending_safety_factor = 0.0;  ///< S_F = allowable / sigma_F [-]
};

/// Stress of one tooth carrying normal load P_d [N] over contact length F_c [m] (eq 18). A tooth
/// without load has zero stress and infinite safety reported as the largest double.
ToothStress tooth_stress(const CouplingGeometry& coupling, double tooth_load_n,
                         double contact_length_m);

}  // namespace gc
