// The service instances of a domain as their status topic shows them (gearcoupling/status,
// docs/protocol.md), kept per instance with its liveness: what `gearcoupling status`, the
// dashboard and its /metrics read. Read-only: it never writes to the domain.
#pragma once

#include <dds/dds.h>

#include <chrono>
#include <cstdint>
#include <map>
#include <mutex>
#include <string_view>
#include <vector>

#include "client/instance_info.h"
#include "protocol/dds_entity.h"

namespace gc::status {

/// kAlive: its status is fresh. kStale: it went without a goodbye (its status writer's lease
/// lapsed: killed, hung, cut off) or no status came for the stale time. kStopped: a graceful
/// stop (it said accepting = false, then disposed its status).
enum class Liveness { kAlive, kStale, kStopped };

/// "alive", "stale", "stopped".
std::string_view to_string(Liveness liveness);

struct InstanceView {
  client::InstanceInfo info;  ///< as its latest status sample described it
  Liveness liveness = Liveness::kAlive;
  double status_age_s = 0.0;  ///< since that sample arrived [s]
};

struct InstanceBoardOptions {
  /// An instance whose status (published every second) is older than this is stale even while
  /// DDS still holds it alive (its lease is 2 s by default).
  std::chrono::milliseconds stale_after{3000};
  /// A stale or stopped instance is dropped from the board after this long.
  std::chrono::milliseconds forget_after{std::chrono::minutes(10)};
  /// Instances on the board at most: anyone allowed to publish a status could otherwise grow
  /// the board and /metrics without bound. A new one beyond it takes the place of the stale or
  /// stopped one heard from longest ago, else it is ignored (counted in refused(), logged
  /// once). Each instance's lists and texts are cut too (kMaxCalculations, kMaxCatalogue,
  /// kMaxTextBytes of cell_board.h).
  std::size_t max_instances = 64;
};

/// The calculations and catalogue couplings an instance's status may list on the board: the
/// service has 6 calculations and the NREL catalogue 2 couplings.
inline constexpr std::size_t kMaxCalculations = 32;
inline constexpr std::size_t kMaxCatalogue = 256;

class InstanceBoard {
 public:
  using Clock = std::chrono::steady_clock;

  /// Reads the status topic on `participant` (which must outlive the board) from now on; a
  /// TRANSIENT_LOCAL reader, so every live instance arrives at once. Throws protocol::DdsError.
  explicit InstanceBoard(dds_entity_t participant, InstanceBoardOptions options = {});
  InstanceBoard(const InstanceBoard&) = delete;
  InstanceBoard& operator=(const InstanceBoard&) = delete;

  /// Every instance seen and not yet forgotten, ordered by host, then pid, then id. Forgets
  /// those gone for longer than forget_after.
  std::vector<InstanceView> snapshot();
  /// Status samples ignored because max_instances live instances were on the board.
  std::uint64_t refused();

 private:
  struct Entry {
    client::InstanceInfo info;
    Clock::time_point received;         ///< latest status sample
    Clock::time_point liveness_changed; ///< latest change of DDS instance state
    Liveness dds_liveness = Liveness::kAlive;
  };

  /// Takes every sample the reader holds (Cyclone's listener thread).
  void take();
  /// `id`'s entry, made when new if there is room (or a stale or stopped instance to drop for
  /// it); nullptr, counted and logged once, when not. Call with mutex_ held.
  Entry* admit(std::uint64_t id, Clock::time_point now);
  /// Whether `entry` is alive as of `now`.
  bool alive(const Entry& entry, Clock::time_point now) const;

  InstanceBoardOptions options_;
  std::mutex mutex_;
  std::map<std::uint64_t, Entry> entries_;
  std::map<dds_instance_handle_t, std::uint64_t> handles_;
  std::uint64_t refused_ = 0;
  protocol::Entity topic_;
  protocol::Entity subscriber_;
  protocol::Entity reader_;  // last: deleted first, so no listener call outlives the members
};

}  // namespace gc::status
