// A batch request (protocol/batch_types.h): every case answered with what a single request of it gets,
// from the same core calls (compute.h) and the same error classification (reply_error_from), so
// a case's result equals the single request's bit for bit and its error names the same field.
#pragma once

#include <exception>
#include <functional>

#include "protocol/batch_types.h"
#include "service/catalogue.h"
#include "service/compute.h"

namespace gc::service {

/// The answer to every case of `request`, in order. Each coupling is resolved once (an unknown
/// name or an invalid inline definition is the error of every case naming it); a case whose
/// coupling index is out of range is refused in place (field "coupling"). Once `cancelled`
/// says so (the service's deadline; asked every 16th time the core or the loop would ask), the
/// case being computed and every later one get
/// `deadline_error()`'s error; the cases computed before keep their results.
protocol::BatchResult compute_batch(const Catalogue& catalogue,
                                    const protocol::BatchRequest& request,
                                    const CancelPredicate& cancelled,
                                    const std::function<std::exception_ptr()>& deadline_error);

}  // namespace gc::service
