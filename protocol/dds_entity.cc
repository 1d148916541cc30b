#include "protocol/dds_entity.h"

namespace gc::protocol {

DdsError::DdsError(const std::string& call, std::int32_t code)
    : std::runtime_error(call + " failed: " + dds_strretcode(code)), code_(code) {}

dds_entity_t check_dds(dds_entity_t result, const char* call) {
  if (result < 0) throw DdsError(call, result);
  return result;
}

}  // namespace gc::protocol
