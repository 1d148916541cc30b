#include "client/instance_info.h"

#include <exception>

#include "protocol/wire_inputs.h"

namespace gc::client {
namespace {

std::string text(const char* value) { return value != nullptr ? value : ""; }

}  // namespace

InstanceInfo instance_info_from_wire(const gearcoupling_ServiceStatus& status) {
  InstanceInfo info;
  info.id = status.instance_id;
  info.host = text(status.host);
  info.pid = status.pid;
  info.accepting = status.accepting;
  info.threads = status.threads;
  info.uptime_s = status.uptime_s;
  for (uint32_t k = 0; k < status.calculations._length; ++k) {
    const gearcoupling_CalculationStats& s = status.calculations._buffer[k];
    info.calculations.push_back({text(s.calculation), s.served, s.failed, s.p50_service_time_s,
                                 s.p99_service_time_s, s.refused, s.service_time_sum_s});
  }
  for (uint32_t k = 0; k < status.catalogue._length; ++k) {
    const gearcoupling_CatalogueEntry& entry = status.catalogue._buffer[k];
    info.catalogue.push_back(text(entry.name));
    info.couplings.push_back(
        {text(entry.name), entry.teeth, entry.jam_angle_rad, entry.definition.facewidth_m});
    try {
      info.definitions.push_back(protocol::from_wire(entry.definition));
    } catch (const std::exception&) {
      // A definition the protocol refuses (a name over its bound) is not offered.
    }
  }
  return info;
}

}  // namespace gc::client
