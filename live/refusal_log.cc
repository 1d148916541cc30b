#include "live/refusal_log.h"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

namespace gc::live {

const char* refusal_kind(Refusal kind) {
  switch (kind) {
    case Refusal::batch_bad_name: return "batch_bad_name";
    case Refusal::batch_oversized: return "batch_oversized";
    case Refusal::batch_foreign: return "batch_foreign";
    case Refusal::batch_beyond_max_cells: return "batch_beyond_max_cells";
    case Refusal::swap_bad_name: return "swap_bad_name";
    case Refusal::swap_foreign: return "swap_foreign";
    case Refusal::swap_no_room: return "swap_no_room";
    case Refusal::swap_bad_model: return "swap_bad_model";
  }
  return "unknown";
}

std::string printable(std::string_view text, std::size_t most) {
  std::string out;
  for (unsigned char c : text) {
    if (out.size() >= most) return out + "...";
    if (c >= 0x20 && c < 0x7f) {
      out += static_cast<char>(c);
    } else {
      out += fmt::format("\\x{:02x}", c);
    }
  }
  return out;
}

bool RefusalLog::refuse(Refusal kind, std::string_view reason, std::uint64_t samples,
                        Clock::time_point now) {
  Kind& k = kinds_[index(kind)];
  k.count += 1;
  k.samples += samples;
  k.latest = printable(reason);
  if (k.count == 1) {
    spdlog::warn("{} (refusal {}: the first; more are summarised at most once a second)", k.latest,
                 refusal_kind(kind));
    k.count_at_last_line = k.count;
    k.last_line = now;
    ++lines_;
    return true;
  }
  if (now - k.last_line < summary_every_) return false;
  summarise(kind, k, now);
  return true;
}

void RefusalLog::flush(Clock::time_point now) {
  for (std::size_t i = 0; i < kinds_.size(); ++i) {
    Kind& k = kinds_[i];
    if (k.count > k.count_at_last_line && now - k.last_line >= summary_every_) {
      summarise(static_cast<Refusal>(i), k, now);
    }
  }
}

void RefusalLog::summarise(Refusal kind, Kind& k, Clock::time_point now) {
  spdlog::warn("{} more refusals {} in {:.1f} s ({} so far); the latest: {}",
               k.count - k.count_at_last_line, refusal_kind(kind),
               std::chrono::duration<double>(now - k.last_line).count(), k.count, k.latest);
  k.count_at_last_line = k.count;
  k.last_line = now;
  ++lines_;
}

}  // namespace gc::live
