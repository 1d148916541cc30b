#include "clients/status/status_messages.h"

#include <chrono>
#include <string>

#include "codec/angle_units.h"
#include "protocol/names.h"

namespace gc::status {
namespace {

double unix_seconds_now() {
  return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch())
      .count();
}

}  // namespace

v1::ServiceInstanceRecord to_message(const InstanceView& instance) {
  const client::InstanceInfo& info = instance.info;
  v1::ServiceInstanceRecord record;
  record.set_instance_id(protocol::hex_id(info.id));
  record.set_host(info.host);
  record.set_pid(info.pid);
  record.set_accepting(info.accepting);
  record.set_threads(info.threads);
  record.set_uptime_s(info.uptime_s);
  record.set_state(std::string(to_string(instance.liveness)));
  record.set_status_age_s(instance.status_age_s);
  for (const client::CalculationStatus& c : info.calculations) {
    v1::CalculationFigures* figures = record.add_calculations();
    figures->set_calculation(c.calculation);
    figures->set_served(c.served);
    figures->set_failed(c.failed);
    figures->set_refused(c.refused);
    figures->set_service_time_sum_s(c.service_time_sum_s);
    if (c.called()) {
      figures->set_p50_service_time_s(c.p50_service_time_s);
      figures->set_p99_service_time_s(c.p99_service_time_s);
    }
  }
  for (const client::CatalogueCoupling& coupling : info.couplings) {
    v1::CatalogueCouplingRecord* entry = record.add_catalogue();
    entry->set_name(coupling.name);
    entry->set_teeth(coupling.teeth);
    entry->set_jam_angle_deg(codec::degrees_from_radians(coupling.jam_angle_rad));
    entry->set_facewidth_m(coupling.facewidth_m);
  }
  return record;
}

v1::LiveStatus to_message(const std::vector<InstanceView>& instances,
                          const std::vector<v1::TestCellRecord>& cells) {
  v1::LiveStatus status;
  status.set_time_unix_s(unix_seconds_now());
  for (const InstanceView& instance : instances) *status.add_instances() = to_message(instance);
  for (const v1::TestCellRecord& cell : cells) *status.add_test_cells() = cell;
  return status;
}

void add_learning(const std::vector<v1::MonitorRecord>& monitors,
                  const std::vector<v1::ProposalRecord>& proposals, v1::LiveStatus& status) {
  for (const v1::MonitorRecord& m : monitors) *status.add_monitors() = m;
  for (const v1::ProposalRecord& p : proposals) *status.add_proposals() = p;
}

}  // namespace gc::status
