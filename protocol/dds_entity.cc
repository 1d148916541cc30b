#include "protocol/dds_entity.h"

namespace gc::protocol {

DdsError::DdsError(const std::string& call, std::int32_t code)
    : std::runtime_error(call + " failed: " + dds_strretcode(code)), code_(code) {}

dds_entity_t check_dds(dds_entity_t result, const char* call) {
  if (result < 0) throw DdsError(call, result);
  return result;
}

dds_entity_t create_participant(int domain, const DdsConfig& config) {
  const auto id = static_cast<dds_domainid_t>(domain);
  if (config.source == DdsConfigSource::kInstalled) {
    const dds_entity_t created = dds_create_domain(id, config.uri.c_str());
    // PRECONDITION_NOT_MET: the domain exists already (an earlier participant of this process).
    if (created < 0 && created != DDS_RETCODE_PRECONDITION_NOT_MET) {
      throw DdsError("dds_create_domain(" + config.uri + ")", created);
    }
  }
  return check_dds(dds_create_participant(id, nullptr, nullptr), "dds_create_participant");
}

}  // namespace gc::protocol
