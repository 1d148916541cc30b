// What a failed calculation becomes on the wire, and what a failed reply becomes again at the
// client: the status code, the request member to blame and the core's message.
#pragma once

#include <exception>
#include <cstddef>
#include <string>
#include <string_view>

#include "core/model_error.h"
#include "gearcoupling.h"

namespace gc::protocol {

/// Most bytes of an error reply's `field` or `message` (and so of what the service logs of them):
/// a request may carry megabytes of text, which must not come back whole (issue 9).
inline constexpr std::size_t kMaxEchoBytes = 1024;

struct ReplyError {
  gearcoupling_ReplyStatus status = gearcoupling_STATUS_INTERNAL_ERROR;
  std::string field;    ///< the request member to blame, "" when none
  std::string message;  ///< the core's what(), cut to kMaxEchoBytes (echo_text)
};

/// Classifies the exception in flight: InvalidInput, UnknownCoupling, DeadlineExceeded,
/// NotConverged, other ModelError, anything else (internal). Field and message pass through
/// echo_text.
ReplyError reply_error_from(std::exception_ptr error);

/// `text` unchanged when it has at most `max_bytes` bytes; otherwise its first bytes (cut at
/// a UTF-8 character boundary) and " ... (<n> bytes in all)", at most max_bytes in all.
std::string echo_text(std::string_view text, std::size_t max_bytes = kMaxEchoBytes);

/// "STATUS_INVALID_INPUT", ...
const char* to_string(gearcoupling_ReplyStatus status);

/// Whether `status` refuses the request's input (STATUS_INVALID_INPUT, STATUS_UNKNOWN_COUPLING):
/// the client's doing, not a failure of the service. The service's status counts these apart
/// (CalculationStats.refused), and so does the dashboard's query panel.
bool refuses_input(gearcoupling_ReplyStatus status);

/// A coupling name not in the service's catalogue (field "coupling.catalogue_name").
class UnknownCoupling : public ModelError {
 public:
  explicit UnknownCoupling(const std::string& name, const std::string& known);
};

/// A calculation not answered within the service's per-calculation deadline, or abandoned
/// because the service stops (STATUS_DEADLINE_EXCEEDED, no field).
class DeadlineExceeded : public ModelError {
 public:
  using ModelError::ModelError;
};

/// An error reply, raised at the client. what() is the service's message, which is the core's
/// what() for model errors, so a remote caller prints what an in-process caller prints.
class ServiceError : public ModelError {
 public:
  explicit ServiceError(ReplyError error);
  gearcoupling_ReplyStatus status() const noexcept { return error_.status; }
  const std::string& field() const noexcept { return error_.field; }

 private:
  ReplyError error_;
};

}  // namespace gc::protocol
