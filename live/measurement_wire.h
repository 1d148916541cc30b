// A recording's sample as a live Measurement and back (idl/gearcoupling.idl): SI on the wire
// (speed in rad/s, temperature in K), the recording's units in core (rpm, deg C).
#pragma once

#include "core/recorded_sample.h"
#include "gearcoupling.h"

namespace gc::live {

/// The sample a Measurement carries, its derived inputs (loading direction, rates, phase) not
/// yet set. Throws InvalidInput naming "measurement.<member>" for a NaN or infinite member.
RecordedSample from_wire(const gearcoupling_Measurement& measurement);

/// Storage for the optional members of one Measurement being written (the IDL's @optional
/// members are pointers).
struct MeasurementOptionals {
  double speed_rad_s, temperature_k, applied_my_nm, applied_mz_nm, hub_motion_m;
};

/// `sample` as a Measurement whose optional members point into `optionals`.
gearcoupling_Measurement to_wire(const RecordedSample& sample, unsigned long long sequence_number,
                                 MeasurementOptionals& optionals);

}  // namespace gc::live
