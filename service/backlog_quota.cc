#include "service/backlog_quota.h"

namespace gc::service {

bool BacklogQuota::take(std::uint64_t client_id) {
  if (total_ >= max_total_) return false;
  std::size_t& held = per_client_[client_id];
  if (held >= max_per_client_) return false;
  held += 1;
  total_ += 1;
  return true;
}

void BacklogQuota::give_back(std::uint64_t client_id) {
  const auto found = per_client_.find(client_id);
  if (found == per_client_.end()) return;
  total_ -= 1;
  if (--found->second == 0) per_client_.erase(found);
}

std::size_t BacklogQuota::of(std::uint64_t client_id) const {
  const auto found = per_client_.find(client_id);
  return found == per_client_.end() ? 0 : found->second;
}

}  // namespace gc::service
