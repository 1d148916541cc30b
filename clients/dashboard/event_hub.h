// Fan-out of the dashboard's updates to every connected browser. Each connection has its own
// queue, bounded in updates and in bytes: when a browser reads too slowly its oldest update is
// dropped (the next one carries the whole state anyway), so one slow browser never holds up the
// others or the DDS side, and memory stays bounded. The number of connections is bounded too:
// each holds one of the HTTP server's threads, and the page, /metrics and the query panel need
// the others (issue 23).
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>

namespace gc::dashboard {

class EventQueue {
 public:
  /// At most `capacity` updates and `max_bytes` bytes of them; the newest is always kept.
  EventQueue(std::size_t capacity, std::size_t max_bytes)
      : capacity_(capacity), max_bytes_(max_bytes) {}
  /// Appends `event`, dropping the oldest while the queue is over either bound.
  void push(const std::shared_ptr<const std::string>& event);
  /// The oldest event, waiting up to `timeout`; nullopt on timeout or once closed.
  std::shared_ptr<const std::string> pop(std::chrono::milliseconds timeout);
  void close();
  bool closed() const;
  std::uint64_t dropped() const;

 private:
  const std::size_t capacity_;
  const std::size_t max_bytes_;
  mutable std::mutex mutex_;
  std::condition_variable ready_;
  std::deque<std::shared_ptr<const std::string>> events_;
  std::size_t bytes_ = 0;   ///< the sizes of the queued events (shared ones counted in full)
  std::uint64_t dropped_ = 0;
  bool closed_ = false;
};

class EventHub {
 public:
  /// `queue_capacity`: updates a connection may fall behind before its oldest is dropped;
  /// `queue_bytes`: the same in bytes; `max_subscribers`: connections at once.
  explicit EventHub(std::size_t queue_capacity,
                    std::size_t max_subscribers = std::numeric_limits<std::size_t>::max(),
                    std::size_t queue_bytes = std::numeric_limits<std::size_t>::max())
      : queue_capacity_(queue_capacity), queue_bytes_(queue_bytes), max_subscribers_(max_subscribers) {}
  /// A new connection's queue; nullptr, counted in refused(), when max_subscribers are
  /// connected already.
  std::shared_ptr<EventQueue> subscribe();
  void unsubscribe(const std::shared_ptr<EventQueue>& queue);
  /// Queues `event` for every subscriber (one shared copy).
  void publish(std::string event);
  /// Closes every queue: their readers return at once.
  void close();
  std::size_t subscribers() const;
  /// Updates dropped so far for slow connections, over all connections (gone ones included).
  std::uint64_t dropped() const;
  /// Connections refused so far because max_subscribers were connected.
  std::uint64_t refused() const;

 private:
  const std::size_t queue_capacity_;
  const std::size_t queue_bytes_;
  const std::size_t max_subscribers_;
  mutable std::mutex mutex_;
  std::set<std::shared_ptr<EventQueue>> queues_;
  std::uint64_t dropped_by_gone_ = 0;
  std::uint64_t refused_ = 0;
  bool closed_ = false;
};

}  // namespace gc::dashboard
