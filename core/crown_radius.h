// Hub face crown radius R_F from the lead modification (Table 1 gives "0.78 mm at tooth
// edges", not R_F). Reading: d is the crown drop of one flank at the tooth edge, F/2 from the
// tooth centre, on a circular arc of radius R_F. Then (R_F - d)^2 + (F/2)^2 = R_F^2, so
//   R_F = ((F/2)^2 + d^2) / (2 d).
// This is the reading under which eq 25's thickness loss 2 R_F (1 - cos xi) equals 2 d at the
// tooth edge; docs/model.md compares it with the other readings.
#pragma once

namespace gc {

/// R_F [m] from facewidth F [m] and per-flank lead modification d [m]. Both must be > 0.
double crown_radius_from_lead_modification(double facewidth_m, double lead_modification_m);

}  // namespace gc
