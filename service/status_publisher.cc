#include "service/status_publisher.h"

#include <unistd.h>

#include <vector>

#include "gearcoupling.h"
#include "protocol/names.h"
#include "protocol/qos.h"
#include "protocol/samples.h"
#include "protocol/topics.h"
#include "protocol/wire_inputs.h"

namespace gc::service {

using protocol::check_dds;
using protocol::Entity;

StatusPublisher::StatusPublisher(dds_entity_t participant, std::uint64_t instance_id,
                                 unsigned threads, double liveliness_lease_s,
                                 const Catalogue& catalogue, const ServiceStats& stats)
    : instance_id_(instance_id), threads_(threads), catalogue_(catalogue), stats_(stats) {
  char host[256] = {};
  gethostname(host, sizeof(host) - 1);
  host_ = host;
  const protocol::Qos qos = protocol::status_qos(liveliness_lease_s);
  topic_ = protocol::make_status_topic(participant);
  const protocol::Qos partition = protocol::partition_qos(protocol::kStatusPartition);
  publisher_ = Entity(check_dds(dds_create_publisher(participant, partition.get(), nullptr),
                                "dds_create_publisher(status)"));
  writer_ = Entity(check_dds(dds_create_writer(publisher_.get(), topic_.get(), qos.get(), nullptr),
                             "dds_create_writer(status)"));
}

void StatusPublisher::publish(bool accepting) {
  protocol::OwnedSample<gearcoupling_ServiceStatus> sample(gearcoupling_ServiceStatus_desc);
  gearcoupling_ServiceStatus& s = sample.get();
  s.instance_id = instance_id_;
  s.request_partition = protocol::wire_string(protocol::request_partition(instance_id_));
  s.host = protocol::wire_string(host_);
  s.pid = static_cast<int32_t>(getpid());
  s.accepting = accepting;
  s.threads = threads_;
  s.uptime_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();

  const auto snapshot = stats_.snapshot();
  s.calculations._buffer = static_cast<gearcoupling_CalculationStats*>(
      dds_alloc(snapshot.size() * sizeof(gearcoupling_CalculationStats)));
  s.calculations._length = s.calculations._maximum = static_cast<uint32_t>(snapshot.size());
  s.calculations._release = true;
  for (protocol::Calculation calculation : protocol::kAllCalculations) {
    const std::size_t i = protocol::index_of(calculation);
    s.calculations._buffer[i] = gearcoupling_CalculationStats{
        protocol::wire_string(std::string(protocol::to_string(calculation))),
        snapshot[i].served, snapshot[i].failed, snapshot[i].p50_service_time_s,
        snapshot[i].p99_service_time_s, snapshot[i].refused, snapshot[i].service_time_sum_s};
  }

  const auto& couplings = catalogue_.couplings();
  s.catalogue._buffer = couplings.empty()
                            ? nullptr
                            : static_cast<gearcoupling_CatalogueEntry*>(
                                  dds_alloc(couplings.size() * sizeof(gearcoupling_CatalogueEntry)));
  s.catalogue._length = s.catalogue._maximum = static_cast<uint32_t>(couplings.size());
  s.catalogue._release = true;
  std::size_t i = 0;
  for (const auto& [name, geometry] : couplings) {
    gearcoupling_CatalogueEntry& entry = s.catalogue._buffer[i++];
    entry = gearcoupling_CatalogueEntry{};
    entry.name = protocol::wire_string(name);
    entry.teeth = geometry.teeth();
    entry.jam_angle_rad = geometry.jam_angle().angle_rad;
    protocol::to_wire(geometry.definition(), entry.definition);
  }
  dds_write(writer_.get(), &s);
}

void StatusPublisher::dispose() {
  gearcoupling_ServiceStatus key{};
  key.instance_id = instance_id_;
  dds_dispose(writer_.get(), &key);
}

}  // namespace gc::service
