#include "protocol/reply_status.h"

namespace gc::protocol {

namespace {

ReplyError classify(std::exception_ptr error) {
  try {
    std::rethrow_exception(error);
  } catch (const InvalidInput& e) {
    return {gearcoupling_STATUS_INVALID_INPUT, e.field(), e.what()};
  } catch (const UnknownCoupling& e) {
    return {gearcoupling_STATUS_UNKNOWN_COUPLING, "coupling.catalogue_name", e.what()};
  } catch (const DeadlineExceeded& e) {
    return {gearcoupling_STATUS_DEADLINE_EXCEEDED, "", e.what()};
  } catch (const NotConverged& e) {
    return {gearcoupling_STATUS_NOT_CONVERGED, "", e.what()};
  } catch (const ModelError& e) {
    return {gearcoupling_STATUS_MODEL_ERROR, "", e.what()};
  } catch (const std::exception& e) {
    return {gearcoupling_STATUS_INTERNAL_ERROR, "", e.what()};
  } catch (...) {
    return {gearcoupling_STATUS_INTERNAL_ERROR, "", "unknown exception"};
  }
}

// A cut inside a multi-byte UTF-8 character would leave an invalid string: back off over
// continuation bytes (10xxxxxx) to the start of the character.
std::size_t character_boundary(std::string_view text, std::size_t at) {
  while (at > 0 && (static_cast<unsigned char>(text[at]) & 0xC0) == 0x80) --at;
  return at;
}

}  // namespace

ReplyError reply_error_from(std::exception_ptr error) {
  ReplyError reply = classify(error);
  reply.field = echo_text(reply.field);
  reply.message = echo_text(reply.message);
  return reply;
}

std::string echo_text(std::string_view text, std::size_t max_bytes) {
  if (text.size() <= max_bytes) return std::string(text);
  const std::string tail = " ... (" + std::to_string(text.size()) + " bytes in all)";
  if (tail.size() >= max_bytes) return std::string(text.substr(0, character_boundary(text, max_bytes)));
  const std::size_t keep = character_boundary(text, max_bytes - tail.size());
  return std::string(text.substr(0, keep)) + tail;
}

bool refuses_input(gearcoupling_ReplyStatus status) {
  return status == gearcoupling_STATUS_INVALID_INPUT || status == gearcoupling_STATUS_UNKNOWN_COUPLING;
}

const char* to_string(gearcoupling_ReplyStatus status) {
  switch (status) {
    case gearcoupling_STATUS_OK: return "STATUS_OK";
    case gearcoupling_STATUS_INVALID_INPUT: return "STATUS_INVALID_INPUT";
    case gearcoupling_STATUS_UNKNOWN_COUPLING: return "STATUS_UNKNOWN_COUPLING";
    case gearcoupling_STATUS_NOT_CONVERGED: return "STATUS_NOT_CONVERGED";
    case gearcoupling_STATUS_MODEL_ERROR: return "STATUS_MODEL_ERROR";
    case gearcoupling_STATUS_INTERNAL_ERROR: return "STATUS_INTERNAL_ERROR";
    case gearcoupling_STATUS_DEADLINE_EXCEEDED: return "STATUS_DEADLINE_EXCEEDED";
  }
  return "STATUS_UNKNOWN";
}

UnknownCoupling::UnknownCoupling(const std::string& name, const std::string& known)
    : ModelError("coupling.catalogue_name = \"" + name +
                 "\" is not in the service's catalogue (known: " + known + ")") {}

ServiceError::ServiceError(ReplyError error)
    : ModelError(error.message), error_(std::move(error)) {}

}  // namespace gc::protocol
