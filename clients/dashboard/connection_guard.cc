#include "clients/dashboard/connection_guard.h"

namespace gc::dashboard {

bool ConnectionGuard::begin_reading(const std::string& peer) {
  std::lock_guard lock(mutex_);
  std::size_t& reading = reading_[peer];
  if (reading >= limits_.max_reading_per_peer) return false;
  ++reading;
  return true;
}

void ConnectionGuard::end_reading(const std::string& peer) {
  std::lock_guard lock(mutex_);
  const auto found = reading_.find(peer);
  if (found == reading_.end()) return;
  if (--found->second == 0) reading_.erase(found);   // the map holds only peers sending now
}

void ConnectionGuard::count_peer_limit() {
  std::lock_guard lock(mutex_);
  ++refused_peer_limit_;
}

void ConnectionGuard::count_timeout() {
  std::lock_guard lock(mutex_);
  ++timeouts_;
}

void ConnectionGuard::count_foreign_host() {
  std::lock_guard lock(mutex_);
  ++refused_foreign_host_;
}

std::uint64_t ConnectionGuard::refused_peer_limit() const {
  std::lock_guard lock(mutex_);
  return refused_peer_limit_;
}

std::uint64_t ConnectionGuard::timeouts() const {
  std::lock_guard lock(mutex_);
  return timeouts_;
}

std::uint64_t ConnectionGuard::refused_foreign_host() const {
  std::lock_guard lock(mutex_);
  return refused_foreign_host_;
}

std::size_t ConnectionGuard::reading() const {
  std::lock_guard lock(mutex_);
  std::size_t total = 0;
  for (const auto& [peer, count] : reading_) total += count;
  return total;
}

}  // namespace gc::dashboard
