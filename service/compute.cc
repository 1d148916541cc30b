#include "service/compute.h"

namespace gc::service {
namespace {

ContactOptions cancellable(ContactOptions options, const CancelPredicate& cancelled) {
  options.load_sharing.cancelled = cancelled;
  return options;
}

}  // namespace

ToothContact compute(const CouplingGeometry& coupling, const protocol::ToothContactRequest& request,
                     const CancelPredicate& cancelled) {
  return tooth_contact(coupling, request.operating_point,
                       cancellable(request.options, cancelled));
}

protocol::JamAngleResult compute(const CouplingGeometry& coupling,
                                 const protocol::JamAngleRequest&, const CancelPredicate&) {
  return {coupling.jam_angle(), coupling.crown_radius_m(), coupling.crown_radius_derived()};
}

InducedMoments compute(const CouplingGeometry& coupling,
                       const protocol::InducedMomentsRequest& request,
                       const CancelPredicate& cancelled) {
  return induced_moments(coupling, request.operating_point,
                         cancellable(request.options, cancelled));
}

RestoringTorque compute(const CouplingGeometry& coupling,
                        const protocol::RestoringTorqueRequest&, const CancelPredicate&) {
  return restoring_torque(coupling);
}

FrictionEstimate compute(const CouplingGeometry& coupling,
                         const protocol::FrictionEstimateRequest& request,
                         const CancelPredicate&) {
  return estimate_friction(coupling, request.measurement);
}

protocol::ContactAndMoments compute_load_case(const CouplingGeometry& coupling,
                                              const OperatingPoint& point,
                                              const ContactOptions& options,
                                              const CancelPredicate& cancelled) {
  // The summary reads the contact's members, not its table of teeth: the load case without it
  // (core/induced_moments.h), bit for bit the two single calls.
  ToothContact contact;
  const InducedMoments moments = induced_moments(coupling, point, cancellable(options, cancelled), contact);
  return {protocol::summary_of(contact), moments};
}

}  // namespace gc::service
