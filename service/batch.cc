#include "service/batch.h"

#include <optional>
#include <vector>

#include "core/model_error.h"
#include "protocol/reply_status.h"

namespace gc::service {
namespace {

using protocol::BatchCalculation;
using protocol::BatchCaseReply;

void set_error(BatchCaseReply& reply, const protocol::ReplyError& error) {
  reply.status = error.status;
  reply.field = error.field;
  reply.message = error.message;
  reply.value = std::monostate{};
}

// One case, as the single request of its calculation computes it (compute.h).
void compute_case(const CouplingGeometry& coupling, const protocol::BatchRequest& request,
                  const OperatingPoint& point, const CancelPredicate& cancelled,
                  BatchCaseReply& reply) {
  switch (request.calculation) {
    case BatchCalculation::kLoadCase:
      reply.value = compute_load_case(coupling, point, request.options, cancelled);
      return;
    case BatchCalculation::kInducedMoments:
      reply.value = compute(coupling, protocol::InducedMomentsRequest{{}, point, request.options},
                            cancelled);
      return;
    case BatchCalculation::kJamAngle:
      reply.value = compute(coupling, protocol::JamAngleRequest{}, cancelled);
      return;
    case BatchCalculation::kRestoringTorque:
      reply.value = compute(coupling, protocol::RestoringTorqueRequest{}, cancelled);
      return;
  }
}

}  // namespace

protocol::BatchResult compute_batch(const Catalogue& catalogue,
                                    const protocol::BatchRequest& request,
                                    const CancelPredicate& cancelled,
                                    const std::function<std::exception_ptr()>& deadline_error) {
  // Each coupling once: a shared catalogue entry, or an inline definition validated into its
  // own storage; the error of one that fails, for every case naming it.
  std::vector<std::optional<CouplingGeometry>> storage(request.couplings.size());
  std::vector<const CouplingGeometry*> couplings(request.couplings.size(), nullptr);
  std::vector<protocol::ReplyError> coupling_errors(request.couplings.size());
  for (std::size_t i = 0; i < request.couplings.size(); ++i) {
    try {
      couplings[i] = &catalogue.resolve(request.couplings[i], storage[i]);
    } catch (...) {
      coupling_errors[i] = protocol::reply_error_from(std::current_exception());
    }
  }

  // The deadline's predicate reads the clock; asked before every case and every load-sharing
  // iteration it cost 4 % of a batch. Every 16th question reads it: a default case takes a few
  // iterations, the costliest allowed iteration about 0.1 ms, so the deadline is seen within
  // about 2 ms at worst.
  std::uint32_t questions = 0;
  const CancelPredicate throttled = [&cancelled, &questions] {
    return (++questions & 15u) == 0 && cancelled();
  };
  const CancelPredicate& stop = cancelled ? throttled : cancelled;

  protocol::BatchResult result;
  result.calculation = request.calculation;
  result.cases.resize(request.cases.size());
  std::optional<protocol::ReplyError> stopped;  // the deadline's error, once it passed
  for (std::size_t i = 0; i < request.cases.size(); ++i) {
    BatchCaseReply& reply = result.cases[i];
    const protocol::BatchCase& c = request.cases[i];
    if (!stopped && stop && stop()) stopped = protocol::reply_error_from(deadline_error());
    if (stopped) {
      set_error(reply, *stopped);
      continue;
    }
    if (c.coupling >= couplings.size()) {
      set_error(reply, protocol::reply_error_from(std::make_exception_ptr(InvalidInput(
                           "coupling", static_cast<double>(c.coupling),
                           "[0, " + std::to_string(couplings.size() - 1) +
                               "] (an index into the couplings)"))));
      continue;
    }
    if (couplings[c.coupling] == nullptr) {
      set_error(reply, coupling_errors[c.coupling]);
      continue;
    }
    try {
      compute_case(*couplings[c.coupling], request, c.operating_point, stop, reply);
    } catch (const Cancelled&) {
      stopped = protocol::reply_error_from(deadline_error());
      set_error(reply, *stopped);
    } catch (...) {
      set_error(reply, protocol::reply_error_from(std::current_exception()));
    }
  }
  return result;
}

}  // namespace gc::service
