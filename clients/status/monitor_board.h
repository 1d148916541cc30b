// What the monitors publish beside the health (docs/protocol.md, "Proposals, swaps and the
// monitor"): each test cell's proposal (gearcoupling/live/proposal) and each monitor's status
// with its refusals and the audit trail of swaps (gearcoupling/live/monitor), as the records of
// idl/live_status.proto. Read by `gearcoupling proposals`, `status`, `swap-model --proposal` and
// the dashboard. Read-only; bounded as the cell board is.
#pragma once

#include <dds/dds.h>

#include <chrono>
#include <condition_variable>
#include <functional>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "idl/live_status.pb.h"
#include "protocol/dds_entity.h"

namespace gc::status {

namespace v1 = ::gearcoupling::v1;

/// The longest model text a proposal keeps [bytes]; a longer one is cut (and then refused by the
/// monitor if applied): a model file is a few kB.
inline constexpr std::size_t kMaxModelTextBytes = 256 * 1024;

class MonitorBoard {
 public:
  /// Reads both topics on `participant` (which must outlive the board); at most `max_entries`
  /// proposals and as many monitors (new ones beyond are ignored). Throws protocol::DdsError.
  explicit MonitorBoard(dds_entity_t participant, std::size_t max_entries = 64);
  MonitorBoard(const MonitorBoard&) = delete;
  MonitorBoard& operator=(const MonitorBoard&) = delete;

  /// Every test cell's latest proposal (disposed ones dropped), by test cell.
  std::vector<v1::ProposalRecord> proposals();
  /// Every live monitor's latest status, by monitor id.
  std::vector<v1::MonitorRecord> monitors();
  /// Waits, woken by each proposal, until `ready` holds for `test_cell`'s proposal or `timeout`
  /// passes; returns the latest either way (nullopt: none).
  std::optional<v1::ProposalRecord> wait_for(const std::string& test_cell,
                                             const std::function<bool(const v1::ProposalRecord&)>& ready,
                                             std::chrono::milliseconds timeout);

 private:
  void take_proposals();
  void take_monitors();

  std::size_t max_entries_;
  std::mutex mutex_;
  std::condition_variable changed_;
  std::map<std::string, v1::ProposalRecord> proposals_;
  std::map<std::string, v1::MonitorRecord> monitors_;
  protocol::Entity proposal_topic_, monitor_topic_, subscriber_;
  protocol::Entity proposal_reader_, monitor_reader_;   // last: deleted first
};

}  // namespace gc::status
