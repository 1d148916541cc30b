// Minimum torque that lifts the hub off the sleeve and centres it (Section 4.4, eqs 49-53).
// The readings of the garbled eqs 50-53 are argued in docs/model.md; in short:
// - per-tooth balance: the torque's load per tooth T / (N R) [cos(phi)] must carry the weight
//   share of each supporting tooth, (W_c + 0.5 W_sh) / N_c, so T_m = N R W / N_c (eq 52) and
//   T_m = N R W / (N_c cos(phi)) (eq 50);
// - the threshold (W_c + 0.5 W_sh) R^2 / (2C) of eqs 51 and 53 is a length only if C there is
//   the mesh's torsional stiffness N C R^2 [N·m/rad]: it reads W / (2 N C), the hub's sag.
#pragma once

#include <string_view>

namespace gc {

class CouplingGeometry;

enum class RootContact {
  kSleeveSides,   ///< Delta_c < Delta_r: teeth at the sleeve sides carry the hub (eqs 52-53)
  kSleeveBottom,  ///< Delta_c >= Delta_r: the hub rests on the sleeve bottom (eqs 50-51)
};

std::string_view to_string(RootContact contact);

struct RestoringTorque {
  double torque_nm = 0.0;               ///< T_m [N·m]
  RootContact contact = RootContact::kSleeveSides;
  int teeth_in_contact = 0;             ///< N_c,s (eq 52) or N_c,b (eq 50) [-]
  double accessible_clearance_m = 0.0;  ///< Delta_c = b / (2 sin phi), eq 49 [m]
  double design_clearance_m = 0.0;      ///< Delta_r: sleeve root to hub tip, radial [m]
  double supported_weight_n = 0.0;      ///< W_c + 0.5 W_sh [N]
  double sag_m = 0.0;                   ///< W / (2 N C), the threshold of eqs 51 and 53 [m]
};

/// Eqs 49-53 for the coupling's weights. The case follows the geometry: Delta_c (eq 49)
/// against the design root clearance Delta_r.
RestoringTorque restoring_torque(const CouplingGeometry& coupling);

}  // namespace gc
