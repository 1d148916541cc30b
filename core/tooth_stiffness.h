// Single-pair tooth stiffness of Section 4.1.
#pragma once

namespace gc {

/// Elasticity form factor Z_i = Y_i / (0.76 + 7.25 Y_i) [-], eq 6, from AGMA form factor Y_i.
double elasticity_factor(double form_factor);

/// Single-pair stiffness C = F E Z1 Z2 / (Z1 + Z2) [N/m], eq 5.
double single_pair_stiffness(double facewidth_m, double youngs_modulus_pa, double form_factor_hub,
                             double form_factor_sleeve);

}  // namespace gc
