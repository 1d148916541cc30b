#include "live/swap_audit_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <sstream>
#include <type_traits>

#include "core/model_error.h"

namespace gc::live {
namespace {

constexpr const char* kFileName = "swap_audit.log";
constexpr const char* kRotatedName = "swap_audit.log.1";

std::uint64_t fnv1a64(const std::string& text) {
  std::uint64_t hash = 14695981039346656037ull;
  for (unsigned char byte : text) {
    hash ^= byte;
    hash *= 1099511628211ull;
  }
  return hash;
}

/// Percent-encodes what would split or end a line; "-" is the empty text. At most
/// kMaxFieldBytes: a longer text is cut and ends in "...", so no name makes a line long.
std::string encode(const std::string& text) {
  if (text.empty()) return "-";
  constexpr std::size_t most = SwapAuditFile::kMaxFieldBytes;
  std::string out;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const unsigned char byte = static_cast<unsigned char>(text[i]);
    const std::string piece =
        byte <= 0x20 || byte == '%' || byte == 0x7f || (byte == '-' && text.size() == 1)
            ? fmt::format("%{:02X}", byte)
            : std::string(1, static_cast<char>(byte));
    const bool last = i + 1 == text.size();
    if (out.size() + piece.size() + (last ? 0 : 3) > most) return out + "...";
    out += piece;
  }
  return out;
}

int hex_digit(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  return -1;
}

std::string decode(const std::string& field, const char* name) {
  if (field == "-") return "";
  std::string out;
  for (std::size_t i = 0; i < field.size(); ++i) {
    if (field[i] != '%') {
      out += field[i];
      continue;
    }
    const int hi = i + 2 < field.size() ? hex_digit(field[i + 1]) : -1;
    const int lo = i + 2 < field.size() ? hex_digit(field[i + 2]) : -1;
    if (hi < 0 || lo < 0) throw InvalidInput(name, "'" + field + "' has a bad %-escape");
    out += static_cast<char>(hi * 16 + lo);
    i += 2;
  }
  return out;
}

std::uint64_t parse_hex16(const std::string& field, const char* name) {
  if (field.size() != 16 || field.find_first_not_of("0123456789abcdef") != std::string::npos) {
    throw InvalidInput(name, "'" + field + "' is not 16 hex digits");
  }
  return std::strtoull(field.c_str(), nullptr, 16);
}

/// A number as the whole of `field` (strtod/strtoll accept a prefix only).
template <typename T>
T parse_number(const std::string& field, const char* name) {
  errno = 0;
  char* end = nullptr;
  T value{};
  if constexpr (std::is_floating_point_v<T>) {
    value = std::strtod(field.c_str(), &end);
  } else if constexpr (std::is_signed_v<T>) {
    value = std::strtoll(field.c_str(), &end, 10);
  } else {
    value = std::strtoull(field.c_str(), &end, 10);
  }
  if (field.empty() || end != field.c_str() + field.size() || errno != 0 ||
      (field[0] == '-' && !std::is_signed_v<T>)) {
    throw InvalidInput(name, "'" + field + "' is not a number");
  }
  return value;
}

std::vector<std::string> split(const std::string& payload) {
  std::vector<std::string> fields;
  std::istringstream in(payload);
  for (std::string field; in >> field;) fields.push_back(field);
  return fields;
}

struct Loaded {
  std::vector<SwapEntry> swaps;                 // oldest first
  std::map<std::uint64_t, std::size_t> by_id;   // index in swaps
};

/// The entry of a `swap` line's 17 fields; throws InvalidInput naming the field that does not parse.
SwapEntry parse_swap(const std::vector<std::string>& f) {
  SwapEntry e;
  e.id = parse_hex16(f[1], "id");
  e.at = std::chrono::system_clock::time_point(std::chrono::duration_cast<std::chrono::system_clock::duration>(
      std::chrono::nanoseconds(parse_number<std::int64_t>(f[2], "at_ns"))));
  e.test_cell = decode(f[3], "test_cell");
  e.proposal_id = parse_hex16(f[4], "proposal_id");
  e.before_rmse_nm[0] = parse_number<double>(f[5], "before_msy_rmse_nm");
  e.before_rmse_nm[1] = parse_number<double>(f[6], "before_msz_rmse_nm");
  e.after_rmse_nm[0] = parse_number<double>(f[7], "after_msy_rmse_nm");
  e.after_rmse_nm[1] = parse_number<double>(f[8], "after_msz_rmse_nm");
  e.after_samples = parse_number<std::uint64_t>(f[9], "after_samples");
  e.writer = decode(f[10], "writer");
  e.written_ns = parse_number<std::int64_t>(f[11], "written_ns");
  e.by = decode(f[12], "by");
  e.source = decode(f[13], "source");
  e.model_before = decode(f[14], "model_before");
  e.model_after = decode(f[15], "model_after");
  e.operator_identity = decode(f[16], "operator_identity");
  e.after_frozen = true;
  e.after_interrupted = true;   // until its `final` after line
  return e;
}

/// Applies one line's payload to `loaded`; throws InvalidInput naming what does not parse.
void apply_line(const std::string& line, Loaded& loaded) {
  if (line.rfind("v1 ", 0) != 0) throw InvalidInput("version", "the line does not start with 'v1 '");
  if (line.size() < 20 || line[19] != ' ') throw InvalidInput("hash", "no 16-digit hash after 'v1 '");
  const std::uint64_t hash = parse_hex16(line.substr(3, 16), "hash");
  const std::string payload = line.substr(20);
  if (fnv1a64(payload) != hash) throw InvalidInput("hash", "the line does not match its hash (damaged)");
  const std::vector<std::string> f = split(payload);
  if (!f.empty() && f[0] == "swap" && f.size() == 17) {
    SwapEntry e = parse_swap(f);
    const auto [at, added] = loaded.by_id.emplace(e.id, loaded.swaps.size());
    if (added) {
      loaded.swaps.push_back(std::move(e));
    } else {
      loaded.swaps[at->second] = std::move(e);   // carried into a newer file: the same swap
    }
  } else if (!f.empty() && f[0] == "after" && (f.size() == 5 || f.size() == 6)) {
    const auto found = loaded.by_id.find(parse_hex16(f[1], "id"));
    const double msy = parse_number<double>(f[2], "after_msy_rmse_nm");
    const double msz = parse_number<double>(f[3], "after_msz_rmse_nm");
    const std::uint64_t samples = parse_number<std::uint64_t>(f[4], "after_samples");
    const std::string state = f.size() == 6 ? f[5] : "final";
    if (state != "following" && state != "final") {
      throw InvalidInput("state", "'" + state + "' is neither 'following' nor 'final'");
    }
    if (found == loaded.by_id.end()) return;   // its swap was rotated out
    SwapEntry& e = loaded.swaps[found->second];
    e.after_rmse_nm[0] = msy;
    e.after_rmse_nm[1] = msz;
    e.after_samples = samples;
    e.after_interrupted = state == "following";
  } else {
    throw InvalidInput("kind", "not a swap line of 17 fields nor an after line of 5 or 6 (" +
                                   std::to_string(f.size()) + " fields)");
  }
}

/// Reads `path` into `loaded`, logging and skipping what does not parse; a torn last line is
/// cut off the file when `cut_torn_tail`.
void load_file(const std::filesystem::path& path, Loaded& loaded, bool cut_torn_tail) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return;
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  std::size_t at = 0, line_number = 0;
  while (at < text.size()) {
    ++line_number;
    const std::size_t end = text.find('\n', at);
    if (end == std::string::npos) {
      spdlog::error("swap audit {}: line {} is torn ({} bytes without an end of line: a write cut "
                    "off by a kill or a crash); dropped{}", path.string(), line_number,
                    text.size() - at, cut_torn_tail ? " and cut off the file" : "");
      if (cut_torn_tail) {
        std::error_code error;
        std::filesystem::resize_file(path, at, error);
        if (error) spdlog::error("swap audit {}: torn line not cut off: {}", path.string(), error.message());
      }
      return;
    }
    try {
      apply_line(text.substr(at, end - at), loaded);
    } catch (const InvalidInput& error) {
      spdlog::error("swap audit {}: line {} skipped: {}", path.string(), line_number, error.what());
    }
    at = end + 1;
  }
}

std::string fixed_number(double value) { return fmt::format("{}", value); }

std::int64_t ns_since_epoch(std::chrono::system_clock::time_point at) {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(at.time_since_epoch()).count();
}

void sync_directory(const std::filesystem::path& dir) {
  const int fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

/// A loaded swap as the lines that load it back: its swap line (with its after-figures), and a
/// `final` after line unless it was cut off by a kill (then it loads as interrupted again).
std::string record_lines(const SwapEntry& e) {
  std::string lines = audit_line(swap_record_payload(e));
  if (!e.after_interrupted) lines += audit_line(after_record_payload(e, AfterState::final));
  return lines;
}

/// What a rotation keeps (SwapAuditFile's top comment): per test cell its latest kKeptPerCell,
/// cells with the most recent swap first, as long as they fit `budget` bytes; then the most
/// recent others that fit. Oldest first.
struct Retained {
  std::vector<const SwapEntry*> entries;
  std::size_t cells_kept = 0, cells_dropped = 0;
};

Retained retained(const std::vector<SwapEntry>& swaps, std::uintmax_t budget) {
  std::map<std::string, std::vector<const SwapEntry*>> by_cell;
  for (const SwapEntry& e : swaps) by_cell[e.test_cell].push_back(&e);
  std::vector<std::vector<const SwapEntry*>*> cells;
  for (auto& [cell, entries] : by_cell) {
    std::stable_sort(entries.begin(), entries.end(),
                     [](const SwapEntry* a, const SwapEntry* b) { return a->at < b->at; });
    cells.push_back(&entries);
  }
  std::stable_sort(cells.begin(), cells.end(), [](const auto* a, const auto* b) {
    return a->back()->at > b->back()->at;
  });
  Retained kept;
  std::uintmax_t used = 0;
  std::vector<const SwapEntry*> rest;
  for (const auto* cell : cells) {
    const std::size_t first = cell->size() > SwapAuditFile::kKeptPerCell
                                  ? cell->size() - SwapAuditFile::kKeptPerCell : 0;
    std::uintmax_t bytes = 0;
    for (std::size_t i = first; i < cell->size(); ++i) bytes += record_lines(*(*cell)[i]).size();
    if (used + bytes > budget) {
      ++kept.cells_dropped;
      continue;
    }
    used += bytes;
    ++kept.cells_kept;
    kept.entries.insert(kept.entries.end(), cell->begin() + static_cast<std::ptrdiff_t>(first), cell->end());
    rest.insert(rest.end(), cell->begin(), cell->begin() + static_cast<std::ptrdiff_t>(first));
  }
  std::stable_sort(rest.begin(), rest.end(),
                   [](const SwapEntry* a, const SwapEntry* b) { return a->at > b->at; });
  for (const SwapEntry* e : rest) {
    const std::size_t bytes = record_lines(*e).size();
    if (used + bytes > budget) break;
    used += bytes;
    kept.entries.push_back(e);
  }
  std::stable_sort(kept.entries.begin(), kept.entries.end(),
                   [](const SwapEntry* a, const SwapEntry* b) { return a->at < b->at; });
  return kept;
}

}  // namespace

std::string swap_record_payload(const SwapEntry& e) {
  return fmt::format("swap {:016x} {} {} {:016x} {} {} {} {} {} {} {} {} {} {} {} {}", e.id,
                     ns_since_epoch(e.at), encode(e.test_cell), e.proposal_id,
                     fixed_number(e.before_rmse_nm[0]), fixed_number(e.before_rmse_nm[1]),
                     fixed_number(e.after_rmse_nm[0]), fixed_number(e.after_rmse_nm[1]),
                     e.after_samples, encode(e.writer), e.written_ns, encode(e.by), encode(e.source),
                     encode(e.model_before), encode(e.model_after), encode(e.operator_identity));
}

std::string after_record_payload(const SwapEntry& e, AfterState state) {
  return fmt::format("after {:016x} {} {} {} {}", e.id, fixed_number(e.after_rmse_nm[0]),
                     fixed_number(e.after_rmse_nm[1]), e.after_samples,
                     state == AfterState::final ? "final" : "following");
}

std::string audit_line(const std::string& payload) {
  return fmt::format("v1 {:016x} {}\n", fnv1a64(payload), payload);
}

SwapAuditFile::SwapAuditFile(std::filesystem::path state_dir, std::uintmax_t rotate_bytes)
    : dir_(std::move(state_dir)), path_(dir_ / kFileName), rotate_bytes_(rotate_bytes) {
  std::error_code error;
  if (!std::filesystem::is_directory(dir_, error)) {
    throw InvalidInput("--state-dir", "'" + dir_.string() + "' is not a directory (the monitor "
                       "keeps its audit trail of model swaps there)");
  }
  open_for_append();
}

SwapAuditFile::~SwapAuditFile() {
  if (fd_ >= 0) ::close(fd_);
}

void SwapAuditFile::open_for_append() {
  fd_ = ::open(path_.c_str(), O_WRONLY | O_APPEND | O_CREAT | O_CLOEXEC, 0640);
  if (fd_ < 0) {
    throw InvalidInput("--state-dir", "cannot open '" + path_.string() + "' for appending: " +
                       std::strerror(errno));
  }
  sync_directory(dir_);   // the file's name survives a power cut as its records do
  std::error_code error;
  size_ = std::filesystem::file_size(path_, error);
  if (error) size_ = 0;
}

std::vector<SwapEntry> SwapAuditFile::load(std::size_t keep) {
  Loaded loaded;
  load_file(dir_ / kRotatedName, loaded, false);
  load_file(path_, loaded, true);
  std::error_code error;
  size_ = std::filesystem::file_size(path_, error);
  if (error) size_ = 0;
  std::vector<SwapEntry>& swaps = loaded.swaps;
  // A swap carried into a newer file (carry()) may stand after later ones once the file it was
  // first written in is dropped.
  std::stable_sort(swaps.begin(), swaps.end(),
                   [](const SwapEntry& a, const SwapEntry& b) { return a.at < b.at; });
  // As the trail in memory drops them: a cell of many swaps gives up its oldest first.
  while (swaps.size() > keep) swaps.erase(swaps.begin() + static_cast<std::ptrdiff_t>(fair_evictee(swaps)));
  spdlog::info("swap audit {}: {} swaps loaded", path_.string(), swaps.size());
  return std::move(swaps);
}

bool SwapAuditFile::append_swap(const SwapEntry& entry) {
  return append(swap_record_payload(entry), true);
}

bool SwapAuditFile::append_after(const SwapEntry& entry, AfterState state, bool flush) {
  return append(after_record_payload(entry, state), flush);
}

void SwapAuditFile::carry(const std::vector<const SwapEntry*>& followed) {
  std::string lines;
  for (const SwapEntry* entry : followed) {
    const std::string line = audit_line(swap_record_payload(*entry));
    if (size_ + lines.size() + line.size() > rotate_bytes_ / 2) {
      spdlog::error("swap audit {}: swap {:016x} of test cell {} not carried into the new file "
                    "(its records are too long); it leaves the trail with the rotated file",
                    path_.string(), entry->id, entry->test_cell);
      continue;
    }
    lines += line;
  }
  if (!lines.empty()) write_out(lines, true, "carried swaps");
}

void SwapAuditFile::rotate() {
  ::close(fd_);
  fd_ = -1;
  std::error_code error;
  if (compact_into_rotated()) {
    std::filesystem::remove(path_, error);   // all it held worth keeping is in .1 now
  } else {
    std::filesystem::rename(path_, dir_ / kRotatedName, error);
  }
  if (error) spdlog::error("swap audit {}: not rotated: {}", path_.string(), error.message());
  try {
    open_for_append();
  } catch (const InvalidInput& e) {
    spdlog::error("swap audit: {}", e.what());
  }
}

bool SwapAuditFile::compact_into_rotated() {
  Loaded loaded;
  load_file(dir_ / kRotatedName, loaded, false);
  load_file(path_, loaded, false);
  const auto kept = retained(loaded.swaps, rotate_bytes_);
  std::string text;
  for (const SwapEntry* e : kept.entries) text += record_lines(*e);
  if (kept.cells_dropped > 0) {
    spdlog::error("swap audit {}: rotation kept the latest {} swaps of {} test cells, not the {} "
                  "test cells swapped longest ago: their records do not fit {} bytes",
                  path_.string(), kKeptPerCell, kept.cells_kept, kept.cells_dropped, rotate_bytes_);
  }
  // Written aside and renamed over the old .1: a kill leaves the old one or the new one whole.
  const std::filesystem::path aside = dir_ / (std::string(kRotatedName) + ".new");
  const int fd = ::open(aside.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0640);
  if (fd < 0) {
    spdlog::error("swap audit {}: cannot compact ({}): rotated whole", aside.string(), std::strerror(errno));
    return false;
  }
  std::size_t written = 0;
  while (written < text.size()) {
    const ssize_t n = ::write(fd, text.data() + written, text.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;
    written += static_cast<std::size_t>(n);
  }
  const bool whole = written == text.size() && ::fdatasync(fd) == 0;
  ::close(fd);
  std::error_code error;
  if (whole) std::filesystem::rename(aside, dir_ / kRotatedName, error);
  if (!whole || error) {
    spdlog::error("swap audit {}: cannot compact ({}): rotated whole", aside.string(),
                  error ? error.message() : std::string(std::strerror(errno)));
    std::filesystem::remove(aside, error);
    return false;
  }
  sync_directory(dir_);
  return true;
}

bool SwapAuditFile::append(const std::string& payload, bool flush) {
  const std::string line = audit_line(payload);
  const bool rotated = size_ > 0 && size_ + line.size() > rotate_bytes_;
  if (rotated) rotate();
  write_out(line, flush, payload);
  return rotated;
}

void SwapAuditFile::write_out(const std::string& lines, bool flush, const std::string& what) {
  if (fd_ < 0) {
    spdlog::error("swap audit {}: not open, record lost: {}", path_.string(), what);
    return;
  }
  // One write() of whole lines with O_APPEND: a kill leaves them whole or cut, never
  // interleaved; fdatasync before the swap is published, so what the status shows is on disk.
  std::size_t written = 0;
  while (written < lines.size()) {
    const ssize_t n = ::write(fd_, lines.data() + written, lines.size() - written);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      spdlog::error("swap audit {}: record not written ({}): {}", path_.string(),
                    std::strerror(errno), what);
      return;
    }
    written += static_cast<std::size_t>(n);
  }
  size_ += lines.size();
  if (flush && ::fdatasync(fd_) != 0) {
    spdlog::error("swap audit {}: fdatasync failed ({})", path_.string(), std::strerror(errno));
  }
}

}  // namespace gc::live
