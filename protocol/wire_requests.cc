#include "protocol/wire_requests.h"

#include "protocol/wire_inputs.h"

namespace gc::protocol {

void to_wire(const ToothContactRequest& in, gearcoupling_ToothContactRequest& out) {
  to_wire(in.coupling, out.coupling);
  to_wire(in.operating_point, out.operating_point);
  to_wire(in.options, out.options);
}

void to_wire(const JamAngleRequest& in, gearcoupling_JamAngleRequest& out) {
  to_wire(in.coupling, out.coupling);
}

void to_wire(const InducedMomentsRequest& in, gearcoupling_InducedMomentsRequest& out) {
  to_wire(in.coupling, out.coupling);
  to_wire(in.operating_point, out.operating_point);
  to_wire(in.options, out.options);
}

void to_wire(const RestoringTorqueRequest& in, gearcoupling_RestoringTorqueRequest& out) {
  to_wire(in.coupling, out.coupling);
}

void to_wire(const FrictionEstimateRequest& in, gearcoupling_FrictionEstimateRequest& out) {
  to_wire(in.coupling, out.coupling);
  to_wire(in.measurement, out.measurement);
}

ToothContactRequest from_wire(const gearcoupling_ToothContactRequest& in) {
  return ToothContactRequest{from_wire(in.coupling), from_wire(in.operating_point),
                             from_wire(in.options)};
}

JamAngleRequest from_wire(const gearcoupling_JamAngleRequest& in) {
  return JamAngleRequest{from_wire(in.coupling)};
}

InducedMomentsRequest from_wire(const gearcoupling_InducedMomentsRequest& in) {
  return InducedMomentsRequest{from_wire(in.coupling), from_wire(in.operating_point),
                               from_wire(in.options)};
}

RestoringTorqueRequest from_wire(const gearcoupling_RestoringTorqueRequest& in) {
  return RestoringTorqueRequest{from_wire(in.coupling)};
}

FrictionEstimateRequest from_wire(const gearcoupling_FrictionEstimateRequest& in) {
  return FrictionEstimateRequest{from_wire(in.coupling), from_wire(in.measurement)};
}

}  // namespace gc::protocol
