// The load cases the coupling and model fuzzers put through a coupling that validated: a few
// points inside the range the model covers, so a strange but accepted geometry is also run
// through eqs 5-53 and not only through its validation.
#pragma once

#include <algorithm>
#include <array>

#include "core/coupling_geometry.h"
#include "core/operating_point.h"

namespace gc::fuzz {

inline std::array<OperatingPoint, 3> load_cases(const CouplingGeometry& coupling) {
  const double jam = coupling.jam_angle().angle_rad;
  return {{{1.0e6, 0.0, 0.0, 0.0},
           {2.0e6, std::min(0.5 * jam, 0.004), 0.7, 0.1},
           {1.0e3, 0.95 * jam, -2.0, 0.3}}};
}

}  // namespace gc::fuzz
