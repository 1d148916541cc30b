// The inputs derived from the sequence of samples rather than measured (core/measurement_sample.h):
// the loading direction (core/loading_direction.h), the rates of misalignment and torque
// (core/input_rate.h) and, where the speed is measured, the rotation phase
// (core/rotation_phase.h). One per stream of samples in time order: a recording read from a file
// or a live test cell's run, so both give an effect the same inputs.
#pragma once

#include "core/input_rate.h"
#include "core/loading_direction.h"
#include "core/measurement_sample.h"
#include "core/rotation_phase.h"

namespace gc::analysis {

class DerivedInputs {
 public:
  /// `loading_dead_band_rad` [rad]: a recording's from its own noise (loading_dead_band_rad), a
  /// live stream's as configured, since its noise is not known before it ends.
  DerivedInputs(double loading_dead_band_rad, double still_after_s)
      : loading_(loading_dead_band_rad, still_after_s) {}

  /// Sets the derived inputs of `sample`, the next of the stream. The rotation phase is set when
  /// the sample has a speed (a stream has it on every sample or none).
  void next(MeasurementSample& sample);

 private:
  LoadingDirectionTracker loading_;
  InputRateTracker misalignment_rate_, torque_rate_;
  RotationPhaseIntegrator phase_;
};

}  // namespace gc::analysis
