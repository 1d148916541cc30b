// One row of a recording as the diagnosis reads it: what the model is given and what the sensors
// measured (docs/diagnosis.md).
#pragma once

#include "core/measurement_sample.h"

namespace gc {

struct Observation {
  MeasurementSample sample;  ///< the model's inputs at this instant
  SensorMoments measured;    ///< M_sy', M_sz' from the strain gauges [N·m]
};

}  // namespace gc
