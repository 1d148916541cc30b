#include "clients/status/instance_board.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <tuple>

#include "clients/status/cell_board.h"  // kMaxTextBytes

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

namespace {

/// `info` cut to what the board keeps of one instance: the IDL bounds neither its lists nor its
/// strings.
void bound(client::InstanceInfo& info) {
  if (info.host.size() > kMaxTextBytes) info.host.resize(kMaxTextBytes);
  if (info.calculations.size() > kMaxCalculations) info.calculations.resize(kMaxCalculations);
  for (auto& c : info.calculations) {
    if (c.calculation.size() > kMaxTextBytes) c.calculation.resize(kMaxTextBytes);
  }
  if (info.catalogue.size() > kMaxCatalogue) info.catalogue.resize(kMaxCatalogue);
  if (info.definitions.size() > kMaxCatalogue) info.definitions.resize(kMaxCatalogue);
  if (info.couplings.size() > kMaxCatalogue) info.couplings.resize(kMaxCatalogue);
}

}  // namespace

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
        Entry* admitted = admit(id, now);
        if (admitted == nullptr) continue;
        handles_[info.instance_handle] = id;
        admitted->info = client::instance_info_from_wire(samples[i]);
        bound(admitted->info);
        admitted->received = now;
      }
      const auto handle = handles_.find(info.instance_handle);
      if (handle == handles_.end()) continue;
      Entry& entry = entries_.at(handle->second);
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

bool InstanceBoard::alive(const Entry& entry, Clock::time_point now) const {
  return entry.dds_liveness == Liveness::kAlive && now - entry.received <= options_.stale_after;
}

InstanceBoard::Entry* InstanceBoard::admit(std::uint64_t id, Clock::time_point now) {
  const auto found = entries_.find(id);
  if (found != entries_.end()) return &found->second;
  if (entries_.size() >= options_.max_instances) {
    // Live instances keep their places; the stale or stopped one heard from longest ago goes.
    auto oldest = entries_.end();
    for (auto it = entries_.begin(); it != entries_.end(); ++it) {
      if (alive(it->second, now)) continue;
      if (oldest == entries_.end() || it->second.received < oldest->second.received) oldest = it;
    }
    if (oldest == entries_.end()) {
      if (refused_++ == 0) {
        spdlog::warn("service instance {} ignored: {} instances are on the board, all alive, the "
                     "most it holds; further ones are counted, not logged",
                     protocol::hex_id(id), options_.max_instances);
      }
      return nullptr;
    }
    std::erase_if(handles_, [&](const auto& handle) { return handle.second == oldest->first; });
    entries_.erase(oldest);
  }
  return &entries_[id];
}

std::uint64_t InstanceBoard::refused() {
  std::lock_guard lock(mutex_);
  return refused_;
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
