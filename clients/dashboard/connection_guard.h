// What one peer may hold of the dashboard's HTTP threads (issue 38, finding 5). httplib serves a
// connection on one thread from its accept until it closes, so connections that send their
// request a byte at a time (or nothing) hold threads as long as they like. Here a connection
// has request_timeout to send its whole request (header and body) and read_timeout between two
// reads; and each peer (IP address) has at most max_reading_per_peer connections still sending
// their request: a further one still sending is answered 429 and closed at once (one whose whole
// request has arrived is served, guarded_http_server.cc). So one host holds at most
// that many threads, each for at most request_timeout, and the rest serve the page, /metrics
// and the API.
#pragma once

#include <chrono>
#include <cstdint>
#include <map>
#include <mutex>
#include <string>

namespace gc::dashboard {

struct ConnectionLimits {
  std::chrono::milliseconds request_timeout{5000};   ///< the whole request, from the accept
  std::chrono::milliseconds read_timeout{2000};      ///< between two reads of it
  std::chrono::milliseconds write_timeout{5000};     ///< for each write of the answer
  std::size_t max_reading_per_peer = 8;
};

/// The per-peer count of connections still sending their request, and what was refused.
/// Thread-safe.
class ConnectionGuard {
 public:
  explicit ConnectionGuard(ConnectionLimits limits) : limits_(limits) {}

  const ConnectionLimits& limits() const { return limits_; }
  /// A connection of `peer` starts sending its request: false (and not counted) when the peer
  /// already has max_reading_per_peer doing so.
  bool begin_reading(const std::string& peer);
  /// A connection refused because its peer had max_reading_per_peer sending (429).
  void count_peer_limit();
  /// Its request was read (or the connection ended): the peer's place is free again.
  void end_reading(const std::string& peer);
  /// A request not sent within request_timeout or read_timeout.
  void count_timeout();
  /// A request refused for its Host or Origin (host_allow_list.h).
  void count_foreign_host();

  std::uint64_t refused_peer_limit() const;
  std::uint64_t timeouts() const;
  std::uint64_t refused_foreign_host() const;
  /// Connections sending their request now, all peers.
  std::size_t reading() const;

 private:
  ConnectionLimits limits_;
  mutable std::mutex mutex_;
  std::map<std::string, std::size_t> reading_;   // by peer; absent when 0
  std::uint64_t refused_peer_limit_ = 0, timeouts_ = 0, refused_foreign_host_ = 0;
};

}  // namespace gc::dashboard
