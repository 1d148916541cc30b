#include "core/restoring_torque.h"

#include <cmath>

#include "core/coupling_geometry.h"

namespace gc {

std::string_view to_string(RootContact contact) {
  switch (contact) {
    case RootContact::kSleeveSides: return "sleeve_sides";
    case RootContact::kSleeveBottom: return "sleeve_bottom";
  }
  return "unknown";
}

RestoringTorque restoring_torque(const CouplingGeometry& coupling) {
  const CouplingDefinition& d = coupling.definition();
  const int n = coupling.teeth();
  const double phi = coupling.pressure_angle_rad();
  const double backlash = coupling.backlash_m();  // delta_b
  const double radius = coupling.pitch_radius_m();

  RestoringTorque r;
  r.supported_weight_n = d.coupling_weight_n + 0.5 * d.shaft_weight_per_length_n_per_m * d.shaft_length_m;
  r.accessible_clearance_m = backlash / (2.0 * std::sin(phi));                       // eq 49
  r.design_clearance_m = 0.5 * (coupling.sleeve_root_diameter_m() - d.outer_diameter_m);
  r.sag_m = r.supported_weight_n / (2.0 * n * coupling.mesh_stiffness_n_per_m());
  const double per_tooth_arm = n * radius;  // T / (N R) balances W / N_c

  if (r.accessible_clearance_m < r.design_clearance_m) {
    r.contact = RootContact::kSleeveSides;
    int supporting = 0;  // eq 53, l = 1 .. N/2
    for (int l = 1; l <= n / 2; ++l) {
      if (backlash * (1.0 - std::cos(2.0 * M_PI * l / n)) < r.sag_m) ++supporting;
    }
    r.teeth_in_contact = 2 + 2 * supporting;                                         // N_c,s
    r.torque_nm = per_tooth_arm * r.supported_weight_n / r.teeth_in_contact;         // eq 52
  } else {
    r.contact = RootContact::kSleeveBottom;
    int supporting = 0;  // eq 51, k = N/4 .. 3N/4
    for (int k = n / 4; k <= 3 * n / 4; ++k) {
      if (backlash - r.sag_m / std::cos(phi) >
          2.0 * r.accessible_clearance_m * std::cos(2.0 * M_PI * k / n) * std::sin(phi)) {
        ++supporting;
      }
    }
    r.teeth_in_contact = 2 + supporting;                                             // N_c,b
    r.torque_nm = per_tooth_arm * r.supported_weight_n / (r.teeth_in_contact * std::cos(phi));  // 50
  }
  return r;
}

}  // namespace gc
