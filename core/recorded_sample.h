// One row of a test-cell recording (docs/recordings.md): what went into the coupling and the
// bending moments measured at the sensors.
#pragma once

#include <optional>

#include "core/measurement_sample.h"

namespace gc {

struct RecordedSample {
  MeasurementSample input;              ///< T, zeta, beta, loading direction, optional inputs
  SensorMoments measured;               ///< M_sy', M_sz' as recorded [N·m]
  std::optional<double> hub_motion_m;   ///< hub-sleeve radial motion, where recorded [m]
};

}  // namespace gc
