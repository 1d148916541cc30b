// How many replies the backlog may hold, in all and for one client: a client that does not read
// fills only its own share, so another slow client's replies still find room (issue 9, "a slow
// or dead reader slows only itself"). Not thread-safe: ReplyBacklog calls it under its lock.
#pragma once

#include <cstddef>
#include <cstdint>
#include <unordered_map>

namespace gc::service {

class BacklogQuota {
 public:
  BacklogQuota(std::size_t max_total, std::size_t max_per_client)
      : max_total_(max_total), max_per_client_(max_per_client) {}

  /// Counts one more reply to `client_id`; false (nothing counted) when either limit is reached.
  bool take(std::uint64_t client_id);
  /// One reply to `client_id` left the backlog (written, expired or its writer gone).
  void give_back(std::uint64_t client_id);

  std::size_t total() const { return total_; }
  std::size_t of(std::uint64_t client_id) const;

 private:
  std::size_t max_total_;
  std::size_t max_per_client_;
  std::size_t total_ = 0;
  std::unordered_map<std::uint64_t, std::size_t> per_client_;
};

}  // namespace gc::service
