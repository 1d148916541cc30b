#include "service/compute.h"

namespace gc::service {

ToothContact compute(const CouplingGeometry& coupling,
                     const protocol::ToothContactRequest& request) {
  return tooth_contact(coupling, request.operating_point, request.options);
}

protocol::JamAngleResult compute(const CouplingGeometry& coupling,
                                 const protocol::JamAngleRequest&) {
  return {coupling.jam_angle(), coupling.crown_radius_m(), coupling.crown_radius_derived()};
}

InducedMoments compute(const CouplingGeometry& coupling,
                       const protocol::InducedMomentsRequest& request) {
  return induced_moments(coupling, request.operating_point, request.options);
}

RestoringTorque compute(const CouplingGeometry& coupling,
                        const protocol::RestoringTorqueRequest&) {
  return restoring_torque(coupling);
}

FrictionEstimate compute(const CouplingGeometry& coupling,
                         const protocol::FrictionEstimateRequest& request) {
  return estimate_friction(coupling, request.measurement);
}

}  // namespace gc::service
