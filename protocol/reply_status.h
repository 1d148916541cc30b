// What a failed calculation becomes on the wire, and what a failed reply becomes again at the
// client: the status code, the request member to blame and the core's message.
#pragma once

#include <exception>
#include <string>

#include "core/model_error.h"
#include "gearcoupling.h"

namespace gc::protocol {

struct ReplyError {
  gearcoupling_ReplyStatus status = gearcoupling_STATUS_INTERNAL_ERROR;
  std::string field;    ///< the request member to blame, "" when none
  std::string message;  ///< the core's what(), unchanged
};

/// Classifies the exception in flight: InvalidInput, UnknownCoupling, NotConverged, other
/// ModelError, anything else (internal).
ReplyError reply_error_from(std::exception_ptr error);

/// "STATUS_INVALID_INPUT", ...
const char* to_string(gearcoupling_ReplyStatus status);

/// A coupling name not in the service's catalogue (field "coupling.catalogue_name").
class UnknownCoupling : public ModelError {
 public:
  explicit UnknownCoupling(const std::string& name, const std::string& known);
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
