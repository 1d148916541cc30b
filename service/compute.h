// The core call behind each request: the same functions the in-process CLI calls, so a remote
// result equals the in-process one bit for bit. `cancelled` reaches the core's iterations
// (LoadSharingOptions::cancelled): the service's deadline stops a calculation mid-way, and the
// core throws gc::Cancelled. The calculations without an iteration ignore it.
#pragma once

#include <functional>
#include <optional>

#include "core/coupling_geometry.h"
#include "protocol/batch_types.h"
#include "protocol/jam_angle_result.h"
#include "service/catalogue.h"
#include "protocol/requests.h"
#include "core/friction_estimate.h"
#include "core/induced_moments.h"
#include "core/jam_angle.h"
#include "core/restoring_torque.h"
#include "core/tooth_contact.h"

namespace gc::service {

using CancelPredicate = std::function<bool()>;

ToothContact compute(const CouplingGeometry& coupling, const protocol::ToothContactRequest& request,
                     const CancelPredicate& cancelled);
/// The jam angle is part of the validated geometry (eqs 23-35 run once per coupling).
protocol::JamAngleResult compute(const CouplingGeometry& coupling,
                                 const protocol::JamAngleRequest& request,
                                 const CancelPredicate& cancelled);
InducedMoments compute(const CouplingGeometry& coupling,
                       const protocol::InducedMomentsRequest& request,
                       const CancelPredicate& cancelled);
RestoringTorque compute(const CouplingGeometry& coupling,
                        const protocol::RestoringTorqueRequest& request,
                        const CancelPredicate& cancelled);
FrictionEstimate compute(const CouplingGeometry& coupling,
                         const protocol::FrictionEstimateRequest& request,
                         const CancelPredicate& cancelled);
/// Tooth contact and the moments from it (eqs 5-48), as the in-process `gearcoupling batch`
/// computes a row: a batch's load case.
protocol::ContactAndMoments compute_load_case(const CouplingGeometry& coupling,
                                              const OperatingPoint& point,
                                              const ContactOptions& options,
                                              const CancelPredicate& cancelled);

/// A single request: its coupling resolved by `catalogue` (throws as Catalogue::resolve does),
/// then compute().
template <typename Request>
auto compute_request(const Catalogue& catalogue, const Request& request,
                     const CancelPredicate& cancelled) {
  std::optional<CouplingGeometry> storage;
  return compute(catalogue.resolve(request.coupling, storage), request, cancelled);
}

}  // namespace gc::service
