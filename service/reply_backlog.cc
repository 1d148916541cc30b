#include "service/reply_backlog.h"

#include <map>
#include <set>
#include <vector>

#include <spdlog/spdlog.h>

#include "protocol/names.h"

namespace gc::service {
namespace {

/// How often held replies are tried again: a client that reads again gets its replies within
/// about this much more.
constexpr std::chrono::milliseconds kRetry{1};

}  // namespace

ReplyBacklog::ReplyBacklog(double hold_s, std::size_t max_replies, std::size_t max_per_client,
                           std::function<void(std::uint64_t)> on_expired)
    : hold_(std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(hold_s))),
      on_expired_(std::move(on_expired)),
      quota_(max_replies, max_per_client),
      thread_([this] { retry_loop(); }) {}

ReplyBacklog::~ReplyBacklog() { stop(); }

bool ReplyBacklog::hold(Reply reply) {
  {
    std::lock_guard lock(mutex_);
    if (stopping_ || !quota_.take(reply.client_id)) {
      dropped_ += 1;
      return false;
    }
    reply.expires = Clock::now() + hold_;
    replies_.push_back(std::move(reply));
  }
  wake_.notify_one();
  return true;
}

void ReplyBacklog::stop() {
  {
    std::lock_guard lock(mutex_);
    if (stopping_) return;
    stopping_ = true;
  }
  wake_.notify_all();
  if (thread_.joinable()) thread_.join();
  retry_once(true);
}

std::size_t ReplyBacklog::size() const {
  std::lock_guard lock(mutex_);
  return quota_.total();
}

std::uint64_t ReplyBacklog::written_late() const {
  std::lock_guard lock(mutex_);
  return written_late_;
}

std::uint64_t ReplyBacklog::dropped() const {
  std::lock_guard lock(mutex_);
  return dropped_;
}

void ReplyBacklog::retry_loop() {
  std::unique_lock lock(mutex_);
  while (!stopping_) {
    if (replies_.empty()) {
      wake_.wait(lock, [this] { return stopping_ || !replies_.empty(); });
      continue;
    }
    lock.unlock();
    retry_once(false);
    lock.lock();
    // Polled: Cyclone announces no "window has room" event to wait for.
    wake_.wait_for(lock, kRetry, [this] { return stopping_; });
  }
}

void ReplyBacklog::retry_once(bool final) {
  std::deque<Reply> replies;
  {
    std::lock_guard lock(mutex_);
    replies.swap(replies_);
  }
  const Clock::time_point now = Clock::now();
  std::set<std::uint64_t> full;                   // a write to it timed out in this round
  std::map<std::uint64_t, std::size_t> expired;   // client -> replies dropped in this round
  std::deque<Reply> kept;
  std::vector<std::uint64_t> left;                // the client of each reply that left
  std::uint64_t written = 0;
  std::uint64_t gone = 0;
  for (Reply& reply : replies) {
    const dds_return_t rc = full.count(reply.client_id) != 0
                                ? DDS_RETCODE_TIMEOUT
                                : dds_write(reply.writer, reply.sample.get());
    if (rc == DDS_RETCODE_OK) {
      written += 1;
      left.push_back(reply.client_id);
    } else if (rc != DDS_RETCODE_TIMEOUT) {
      gone += 1;  // the writer was deleted: the client left
      left.push_back(reply.client_id);
    } else if (final || now >= reply.expires) {
      expired[reply.client_id] += 1;
      left.push_back(reply.client_id);
    } else {
      full.insert(reply.client_id);
      kept.push_back(std::move(reply));
    }
  }
  {
    std::lock_guard lock(mutex_);
    written_late_ += written;
    dropped_ += gone;
    for (const std::uint64_t client : left) quota_.give_back(client);
    for (const auto& [client, count] : expired) dropped_ += count;
    // Replies held meanwhile come after the older ones.
    for (Reply& reply : replies_) kept.push_back(std::move(reply));
    replies_.swap(kept);
  }
  for (const auto& [client, count] : expired) {
    spdlog::warn("client={}: {} repl{} dropped: the client did not acknowledge its replies "
                 "within {:.3g} s (reading too slowly, stopped or killed)",
                 protocol::hex_id(client), count, count == 1 ? "y" : "ies",
                 std::chrono::duration<double>(hold_).count());
    if (on_expired_) on_expired_(client);
  }
}

}  // namespace gc::service
