#include "client/reply_error.h"

#include <cstdlib>
#include <optional>
#include <string>

#include "core/model_error.h"
#include "gearcoupling.h"
#include "protocol/reply_status.h"

namespace gc::client {
namespace {

/// The core's InvalidInput whose what() is `message`, if `message` has one of its two forms:
/// "<field> = <value> is out of range: allowed <allowed>" or "<field>: <text>".
std::optional<InvalidInput> invalid_input(const std::string& field, const std::string& message) {
  const std::string ranged = field + " = ";
  const std::string allowed = " is out of range: allowed ";
  if (message.rfind(ranged, 0) == 0) {
    const std::size_t at = message.find(allowed, ranged.size());
    if (at != std::string::npos) {
      const std::string value_text = message.substr(ranged.size(), at - ranged.size());
      char* end = nullptr;
      const double value = std::strtod(value_text.c_str(), &end);
      InvalidInput error(field, value, message.substr(at + allowed.size()));
      if (*end == '\0' && message == error.what()) return error;
    }
  }
  const std::string plain = field + ": ";
  if (message.rfind(plain, 0) == 0) {
    InvalidInput error(field, message.substr(plain.size()));
    if (message == error.what()) return error;
  }
  return std::nullopt;
}

}  // namespace

void throw_reply_error(int status, const char* field_text, const char* message_text) {
  const std::string field = field_text != nullptr ? field_text : "";
  const std::string message = message_text != nullptr ? message_text : "";
  switch (status) {
    case gearcoupling_STATUS_INVALID_INPUT:
      if (auto error = invalid_input(field, message)) throw *error;
      break;
    case gearcoupling_STATUS_NOT_CONVERGED: throw NotConverged(message);
    case gearcoupling_STATUS_MODEL_ERROR: throw ModelError(message);
    default: break;
  }
  throw protocol::ServiceError(
      {static_cast<gearcoupling_ReplyStatus>(status), field, message});
}

}  // namespace gc::client
