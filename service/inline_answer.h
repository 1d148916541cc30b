// Which requests the request listener answers itself, in Cyclone's receive thread, instead of
// handing them to a worker (docs/architecture.md, "Where a request is computed").
//
// A hand-off to a worker costs one wake-up of a sleeping thread: 10-40 us here, more on a host
// whose cores are busy with other work, against 1-3 us of computing for a default request
// (docs/benchmarks.md, "Latency on a busy host"). ddsperf's floor has no hand-off at all. So a
// request whose worst-case cost is bounded near a default request's is answered where it
// arrives. Anything costlier goes to the workers, since the receive thread also carries every
// other client's requests: a slow request there would hold them all up.
#pragma once

#include "core/load_sharing.h"
#include "core/tooth_contact.h"
#include "protocol/batch_types.h"
#include "protocol/requests.h"
#include "service/catalogue.h"

namespace gc::service {

/// Most teeth (N) of a coupling whose requests are answered in the listener: twice the bundled
/// NREL couplings' 100. The core allows 10,000, and every calculation walks the teeth.
inline constexpr int kInlineTeethBound = 200;
/// Most load-sharing work (slices x iterations, eqs 14-22) per tooth answered in the listener:
/// the defaults', 20 slices x 100 iterations. A default request converges in a few iterations
/// (1-3 us); one that runs to the limit costs about a tenth of a millisecond.
inline constexpr long kInlineContactWorkBound = 20L * 100;

/// N of the coupling `coupling` names: the inline definition's or the catalogue entry's; 0 for a
/// name the catalogue lacks (answered at once with an error).
int teeth_of(const protocol::CouplingRef& coupling, const Catalogue& catalogue);

/// True when a request on `teeth` teeth with `options` stays within both bounds.
bool cheap_to_answer(int teeth, const ContactOptions& options);

bool cheap_to_answer(const protocol::ToothContactRequest& request, const Catalogue& catalogue);
bool cheap_to_answer(const protocol::InducedMomentsRequest& request, const Catalogue& catalogue);
/// The jam angle (eqs 23-35), the restoring torque (eqs 49-53) and the friction estimate
/// (eqs 1-4) are closed forms or one bounded root over the geometry: only the teeth count.
bool cheap_to_answer(const protocol::JamAngleRequest& request, const Catalogue& catalogue);
bool cheap_to_answer(const protocol::RestoringTorqueRequest& request, const Catalogue& catalogue);
bool cheap_to_answer(const protocol::FrictionEstimateRequest& request, const Catalogue& catalogue);
/// Never: a batch is up to thousands of requests' work, which would hold up every other
/// client's requests in the receive thread. Batches go to the workers.
bool cheap_to_answer(const protocol::BatchRequest& request, const Catalogue& catalogue);

}  // namespace gc::service
