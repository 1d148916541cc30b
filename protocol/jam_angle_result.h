// The jam angle with the crown radius it was computed for: what a jam-angle request returns
// (R_F is not part of gc::JamAngle, and a catalogue coupling's R_F is known only to the service).
#pragma once

#include "core/jam_angle.h"

namespace gc::protocol {

struct JamAngleResult {
  JamAngle jam;                       ///< eqs 23-35
  double crown_radius_m = 0.0;        ///< R_F [m]
  bool crown_radius_derived = false;  ///< R_F came from the lead modification
};

}  // namespace gc::protocol
