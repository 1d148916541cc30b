#include "live/swap_audit.h"

#include "live/swap_audit_file.h"

#include <algorithm>
#include <vector>

namespace gc::live {

const char* after_state_text(const SwapEntry& entry) {
  if (!entry.after_frozen) return "following";
  return entry.after_interrupted ? "interrupted" : "final";
}

SwapAudit::SwapAudit() = default;

SwapAudit::SwapAudit(const std::filesystem::path& state_dir)
    : SwapAudit(state_dir, SwapAuditFile::kRotateBytes) {}

SwapAudit::SwapAudit(const std::filesystem::path& state_dir, std::uintmax_t rotate_bytes) {
  if (state_dir.empty()) return;
  file_ = std::make_unique<SwapAuditFile>(state_dir, rotate_bytes);
  for (SwapEntry& entry : file_->load(kKept)) entries_.push_back(std::move(entry));
}

SwapAudit::~SwapAudit() = default;

SwapEntry* SwapAudit::latest(const std::string& test_cell) {
  for (auto it = entries_.rbegin(); it != entries_.rend(); ++it) {
    if (it->test_cell == test_cell) return &*it;
  }
  return nullptr;
}

void SwapAudit::add(SwapEntry entry) {
  // The final lines of the swaps it ends are flushed by the swap line's fdatasync: one a swap.
  if (SwapEntry* previous = latest(entry.test_cell)) freeze(*previous, false);
  if (entries_.size() == kKept) {
    const std::size_t leaving = fair_evictee(entries_);
    freeze(entries_[leaving], false);
    entries_.erase(entries_.begin() + static_cast<std::ptrdiff_t>(leaving));
  }
  if (file_ && file_->append_swap(entry)) carry_followed_swaps();   // the others still followed
  entries_.push_back(std::move(entry));
  ++total_;
}

bool SwapAudit::contains(const std::string& writer, std::int64_t written_ns) const {
  for (const SwapEntry& entry : entries_) {
    if (!writer.empty() && entry.writer == writer && entry.written_ns == written_ns) return true;
  }
  return false;
}

void SwapAudit::follow(const std::string& test_cell, const HealthReport& health,
                       std::chrono::steady_clock::time_point now) {
  SwapEntry* entry = latest(test_cell);
  if (entry == nullptr || entry->after_frozen || health.model.model_name != entry->model_after) return;
  for (std::size_t c = 0; c < 2; ++c) entry->after_rmse_nm[c] = health.model.channels[c].rmse_nm;
  entry->after_samples = health.window_samples;
  if (!file_ || entry->after_samples == 0) return;
  FollowWrites& written = follow_writes_[entry->id];
  const bool changed = written.samples != entry->after_samples ||
                       written.rmse_nm[0] != entry->after_rmse_nm[0] ||
                       written.rmse_nm[1] != entry->after_rmse_nm[1];
  if (!changed || now < written.next) return;
  written.interval = written.interval == std::chrono::steady_clock::duration::zero()
                         ? std::chrono::steady_clock::duration(kFirstFollowWrite)
                         : std::min<std::chrono::steady_clock::duration>(2 * written.interval, kMaxFollowWrite);
  written.next = now + written.interval;
  written.samples = entry->after_samples;
  for (std::size_t c = 0; c < 2; ++c) written.rmse_nm[c] = entry->after_rmse_nm[c];
  if (file_->append_after(*entry, AfterState::following, false)) carry_followed_swaps();
}

void SwapAudit::freeze(SwapEntry& entry, bool flush) {
  if (entry.after_frozen) return;
  entry.after_frozen = true;
  follow_writes_.erase(entry.id);
  // Always, samples or not: a swap without its `final` line is loaded as cut off by a kill.
  if (file_ && file_->append_after(entry, AfterState::final, flush)) carry_followed_swaps();
}

void SwapAudit::carry_followed_swaps() {
  std::vector<const SwapEntry*> followed;
  for (const SwapEntry& entry : entries_) {
    if (!entry.after_frozen) followed.push_back(&entry);
  }
  file_->carry(followed);
}

void SwapAudit::freeze(const std::string& test_cell) {
  if (SwapEntry* entry = latest(test_cell)) freeze(*entry, true);
}

void SwapAudit::close() {
  for (SwapEntry& entry : entries_) freeze(entry, true);
}

}  // namespace gc::live
