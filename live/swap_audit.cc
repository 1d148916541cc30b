#include "live/swap_audit.h"

namespace gc::live {

SwapEntry* SwapAudit::latest(const std::string& test_cell) {
  for (auto it = entries_.rbegin(); it != entries_.rend(); ++it) {
    if (it->test_cell == test_cell) return &*it;
  }
  return nullptr;
}

void SwapAudit::add(SwapEntry entry) {
  freeze(entry.test_cell);
  if (entries_.size() == kKept) entries_.pop_front();
  entries_.push_back(std::move(entry));
  ++total_;
}

void SwapAudit::follow(const std::string& test_cell, const HealthReport& health) {
  SwapEntry* entry = latest(test_cell);
  if (entry == nullptr || entry->after_frozen || health.model.model_name != entry->model_after) return;
  for (std::size_t c = 0; c < 2; ++c) entry->after_rmse_nm[c] = health.model.channels[c].rmse_nm;
  entry->after_samples = health.window_samples;
}

void SwapAudit::freeze(const std::string& test_cell) {
  if (SwapEntry* entry = latest(test_cell)) entry->after_frozen = true;
}

}  // namespace gc::live
