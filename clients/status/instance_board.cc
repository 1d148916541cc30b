#include "clients/status/instance_board.h"

#include <algorithm>
#include <tuple>

#include "clients/status/listening_reader.h"
#include "protocol/names.h"
#include "protocol/qos.h"
#include "protocol/topics.h"

namespace gc::status {

using protocol::check_dds;
using protocol::Entity;

std::string_view to_string(Liveness liveness) {
  switch (liveness) {
    case Liveness::kAlive: return "alive";
    case Liveness::kStale: return "stale";
    case Liveness::kStopped: return "stopped";
  }
  return "unknown";
}

InstanceBoard::InstanceBoard(dds_entity_t participant, InstanceBoardOptions options)
    : options_(options), topic_(protocol::make_status_topic(participant)) {
  const protocol::Qos partition = protocol::partition_qos(protocol::kStatusPartition);
  subscriber_ = Entity(check_dds(dds_create_subscriber(participant, partition.get(), nullptr),
                                 "dds_create_subscriber(status)"));
  reader_ = make_listening_reader<&InstanceBoard::take>(
      subscriber_.get(), topic_.get(), protocol::status_reader_qos(), this, "dds_create_reader(status)");
  take();  // samples that arrived before the listener was in place
}

void InstanceBoard::take() {
  take_each_batch<gearcoupling_ServiceStatus>(reader_.get(), [this](const auto& samples) {
    const Clock::time_point now = Clock::now();
    std::lock_guard lock(mutex_);
    for (std::size_t i = 0; i < samples.size(); ++i) {
      const dds_sample_info_t& info = samples.info(i);
      if (info.valid_data) {
        const std::uint64_t id = samples[i].instance_id;
        handles_[info.instance_handle] = id;
        Entry& entry = entries_[id];
        entry.info = client::instance_info_from_wire(samples[i]);
        entry.received = now;
      }
      const auto handle = handles_.find(info.instance_handle);
      if (handle == handles_.end()) continue;
      Entry& entry = entries_[handle->second];
      // A graceful stop publishes accepting = false, then disposes. Cyclone 0.10 also
      // reports a killed instance as disposed once its lease lapses (the lost writer
      // unregisters, and unregistering auto-disposes), so "stopped" needs the goodbye too.
      const Liveness liveness =
          info.instance_state == DDS_IST_ALIVE ? Liveness::kAlive
          : info.instance_state == DDS_IST_NOT_ALIVE_DISPOSED && !entry.info.accepting
              ? Liveness::kStopped
              : Liveness::kStale;
      if (liveness != entry.dds_liveness) entry.liveness_changed = now;
      entry.dds_liveness = liveness;
    }
  });
}

std::vector<InstanceView> InstanceBoard::snapshot() {
  const Clock::time_point now = Clock::now();
  std::vector<InstanceView> views;
  std::lock_guard lock(mutex_);
  for (auto it = entries_.begin(); it != entries_.end();) {
    const Entry& entry = it->second;
    InstanceView view{entry.info, entry.dds_liveness,
                      std::chrono::duration<double>(now - entry.received).count()};
    if (view.liveness == Liveness::kAlive && now - entry.received > options_.stale_after) {
      view.liveness = Liveness::kStale;
    }
    const Clock::time_point gone_since = entry.dds_liveness == Liveness::kAlive
                                             ? entry.received + options_.stale_after
                                             : entry.liveness_changed;
    if (view.liveness != Liveness::kAlive && now - gone_since > options_.forget_after) {
      std::erase_if(handles_, [&](const auto& handle) { return handle.second == it->first; });
      it = entries_.erase(it);
      continue;
    }
    views.push_back(std::move(view));
    ++it;
  }
  std::sort(views.begin(), views.end(), [](const InstanceView& a, const InstanceView& b) {
    return std::tie(a.info.host, a.info.pid, a.info.id) <
           std::tie(b.info.host, b.info.pid, b.info.id);
  });
  return views;
}

}  // namespace gc::status
