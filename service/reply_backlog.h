// Replies a worker could not write at once: the client's reply writer has its window full of
// replies the client has not acknowledged (it reads slowly, is stopped, or was killed and is
// still matched until its lease ends). Since issue 38 the writers are KEEP_LAST
// (protocol::reply_history_depth), which Cyclone 0.10 never makes wait: a write no longer fails
// for a full window, and this backlog stays empty. It is kept for a writer that would. The reply writers never block (max blocking time 0), so
// the worker hands such a reply here and moves on; a thread of this class retries it, again
// without blocking, until it is written or has waited `hold_s`. A slow or dead reader so delays
// only its own replies, never a worker or another client's.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>

#include <dds/dds.h>

#include "protocol/calculation.h"
#include "service/backlog_quota.h"

namespace gc::service {

class ReplyBacklog {
 public:
  using Clock = std::chrono::steady_clock;

  /// One reply not yet written. `sample` points at the IDL sample and keeps it alive.
  struct Reply {
    std::uint64_t client_id = 0;
    std::uint64_t sequence_number = 0;
    protocol::Calculation calculation{};
    dds_entity_t writer = 0;
    std::shared_ptr<const void> sample;
    Clock::time_point expires{};  ///< set by hold()
  };

  /// Holds at most `max_replies` at once, and `max_per_client` for one client. `on_expired(client_id)`
  /// is called (under no lock of this class) when a reply to that client is dropped for
  /// waiting `hold_s`.
  ReplyBacklog(double hold_s, std::size_t max_replies, std::size_t max_per_client,
               std::function<void(std::uint64_t client_id)> on_expired);
  /// stop().
  ~ReplyBacklog();
  ReplyBacklog(const ReplyBacklog&) = delete;
  ReplyBacklog& operator=(const ReplyBacklog&) = delete;

  /// Keeps `reply` to retry; false when `max_replies` in all, or `max_per_client` for its
  /// client, are already held (the reply is dropped).
  bool hold(Reply reply);
  /// Tries every held reply once more, drops the rest, joins the thread. Idempotent.
  void stop();

  std::size_t size() const;
  std::uint64_t written_late() const;  ///< replies written by a retry
  std::uint64_t dropped() const;       ///< replies given up on (expired, full, writer gone)

 private:
  void retry_loop();
  /// One non-blocking attempt at each held reply, at most one failed attempt per client.
  void retry_once(bool final);

  const Clock::duration hold_;
  const std::function<void(std::uint64_t)> on_expired_;
  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::deque<Reply> replies_;
  BacklogQuota quota_;  ///< counts replies_ and those being retried
  bool stopping_ = false;
  std::uint64_t written_late_ = 0;
  std::uint64_t dropped_ = 0;
  std::thread thread_;  ///< last: started once the rest is built
};

}  // namespace gc::service
