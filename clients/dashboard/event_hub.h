// Fan-out of the dashboard's updates to every connected browser. Each connection has its own
// bounded queue: when a browser reads too slowly its oldest update is dropped (the next one
// carries the whole state anyway), so one slow browser never holds up the others or the DDS
// side, and memory stays bounded.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <set>
#include <string>

namespace gc::dashboard {

class EventQueue {
 public:
  explicit EventQueue(std::size_t capacity) : capacity_(capacity) {}
  /// Appends `event`, dropping the oldest when full.
  void push(const std::shared_ptr<const std::string>& event);
  /// The oldest event, waiting up to `timeout`; nullopt on timeout or once closed.
  std::shared_ptr<const std::string> pop(std::chrono::milliseconds timeout);
  void close();
  bool closed() const;
  std::uint64_t dropped() const;

 private:
  const std::size_t capacity_;
  mutable std::mutex mutex_;
  std::condition_variable ready_;
  std::deque<std::shared_ptr<const std::string>> events_;
  std::uint64_t dropped_ = 0;
  bool closed_ = false;
};

class EventHub {
 public:
  /// `queue_capacity`: updates a connection may fall behind before its oldest is dropped.
  explicit EventHub(std::size_t queue_capacity) : queue_capacity_(queue_capacity) {}
  std::shared_ptr<EventQueue> subscribe();
  void unsubscribe(const std::shared_ptr<EventQueue>& queue);
  /// Queues `event` for every subscriber (one shared copy).
  void publish(std::string event);
  /// Closes every queue: their readers return at once.
  void close();
  std::size_t subscribers() const;
  /// Updates dropped so far for slow connections, over all connections (gone ones included).
  std::uint64_t dropped() const;

 private:
  const std::size_t queue_capacity_;
  mutable std::mutex mutex_;
  std::set<std::shared_ptr<EventQueue>> queues_;
  std::uint64_t dropped_by_gone_ = 0;
  bool closed_ = false;
};

}  // namespace gc::dashboard
