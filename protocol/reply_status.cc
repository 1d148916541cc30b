#include "protocol/reply_status.h"

namespace gc::protocol {

ReplyError reply_error_from(std::exception_ptr error) {
  try {
    std::rethrow_exception(error);
  } catch (const InvalidInput& e) {
    return {gearcoupling_STATUS_INVALID_INPUT, e.field(), e.what()};
  } catch (const UnknownCoupling& e) {
    return {gearcoupling_STATUS_UNKNOWN_COUPLING, "coupling.catalogue_name", e.what()};
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

const char* to_string(gearcoupling_ReplyStatus status) {
  switch (status) {
    case gearcoupling_STATUS_OK: return "STATUS_OK";
    case gearcoupling_STATUS_INVALID_INPUT: return "STATUS_INVALID_INPUT";
    case gearcoupling_STATUS_UNKNOWN_COUPLING: return "STATUS_UNKNOWN_COUPLING";
    case gearcoupling_STATUS_NOT_CONVERGED: return "STATUS_NOT_CONVERGED";
    case gearcoupling_STATUS_MODEL_ERROR: return "STATUS_MODEL_ERROR";
    case gearcoupling_STATUS_INTERNAL_ERROR: return "STATUS_INTERNAL_ERROR";
  }
  return "STATUS_UNKNOWN";
}

UnknownCoupling::UnknownCoupling(const std::string& name, const std::string& known)
    : ModelError("coupling.catalogue_name = \"" + name +
                 "\" is not in the service's catalogue (known: " + known + ")") {}

ServiceError::ServiceError(ReplyError error)
    : ModelError(error.message), error_(std::move(error)) {}

}  // namespace gc::protocol
