// What a swap's durable record in the audit trail costs (live/swap_audit.h, swap_audit_file.h):
// the monitor's thread appends the swap's line and waits for fdatasync before it publishes the
// swap, so this is the time a swap holds up the residuals of every test cell. Beside it, in the
// same run and the same directory: the anchor, the same write()s and fdatasync() of the same
// bytes on a plain file (what the disk asks, whatever the code around it), and the after-figures
// a followed swap writes without fdatasync (SwapAudit::follow), against a plain write() of them.
//
// Each benchmark runs a bounded count of appends (kAppends) into a new file of a new directory
// under $GC_BENCH_STATE_DIR (default: the temporary directory; put it on the disk of the
// monitor's --state-dir) and reports each append's p50 and p99 [us] beside Google Benchmark's
// mean. docs/benchmarks.md, "Learning loop", has the command and the figures.
#include <benchmark/benchmark.h>

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "bench/percentile.h"
#include "live/swap_audit.h"
#include "live/swap_audit_file.h"

namespace gc {
namespace {

constexpr int kAppends = 1000;   // 340 kB of lines: below the rotation at 1 MiB

/// A new empty directory under $GC_BENCH_STATE_DIR or the temporary directory, removed with it.
class ScratchDir {
 public:
  ScratchDir() {
    static std::atomic<int> counter{0};
    const char* base = std::getenv("GC_BENCH_STATE_DIR");
    path_ = std::filesystem::path(base != nullptr ? base : std::filesystem::temp_directory_path().string()) /
            ("gc_swap_audit_bench_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
    std::filesystem::create_directories(path_);
  }
  ~ScratchDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

/// A swap as the monitor audits one from a proposal applied by an operator: 250-300 bytes a line.
live::SwapEntry typical_swap(std::uint64_t id) {
  live::SwapEntry e;
  e.id = id;
  e.test_cell = "dyno1";
  e.at = std::chrono::system_clock::now();
  e.by = "alice@test-hall-2";
  e.operator_identity = "operator-shift1";
  e.source = "proposal 3f9c2a7d0b1e4c55";
  e.proposal_id = 0x3f9c2a7d0b1e4c55ull;
  e.model_before = "paper";
  e.model_after = "paper_diagnosed";
  e.before_rmse_nm[0] = 6612.482;
  e.before_rmse_nm[1] = 2954.17;
  e.after_rmse_nm[0] = 1912.3;
  e.after_rmse_nm[1] = 1874.9;
  e.after_samples = 20000;
  e.writer = "0110fa3c00000002000000000000d03";
  e.written_ns = 1'790'000'000'123'456'789;
  return e;
}

/// Times each of kAppends calls of `append(i)` and reports p50 and p99 [us].
template <typename Append>
void time_appends(benchmark::State& state, Append append) {
  std::vector<double> us;
  us.reserve(kAppends);
  int i = 0;
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    append(i++);
    us.push_back(std::chrono::duration<double, std::micro>(std::chrono::steady_clock::now() - start).count());
  }
  state.counters["p50_us"] = bench::percentile(us, 0.50);
  state.counters["p99_us"] = bench::percentile(us, 0.99);
}

/// A plain file opened as SwapAuditFile opens its own (O_APPEND), for the anchors.
class PlainFile {
 public:
  explicit PlainFile(const std::filesystem::path& path)
      : fd_(::open(path.c_str(), O_WRONLY | O_APPEND | O_CREAT | O_CLOEXEC, 0640)) {
    if (fd_ < 0) throw std::runtime_error("cannot open " + path.string());
  }
  ~PlainFile() { ::close(fd_); }
  void write(const std::string& bytes, bool flush) {
    if (::write(fd_, bytes.data(), bytes.size()) != static_cast<ssize_t>(bytes.size())) {
      throw std::runtime_error("short write");
    }
    if (flush && ::fdatasync(fd_) != 0) throw std::runtime_error("fdatasync failed");
  }

 private:
  int fd_;
};

// A swap as the monitor's thread takes it (SwapAudit::add, a swap of the same test cell each
// time): the previous swap's final after line and the new swap's line, two write()s and one
// fdatasync(); the anchor makes the same calls with the same bytes on a plain file.
void BM_SwapAuditAddSwap(benchmark::State& state) {
  ScratchDir dir;
  live::SwapAudit audit(dir.path());
  std::uint64_t id = 0;
  state.counters["line_bytes"] = static_cast<double>(
      live::audit_line(live::after_record_payload(typical_swap(1), live::AfterState::final)).size() +
      live::audit_line(live::swap_record_payload(typical_swap(1))).size());
  time_appends(state, [&](int) { audit.add(typical_swap(++id)); });
}

void BM_AnchorWriteWriteFdatasyncOfTheSameBytes(benchmark::State& state) {
  ScratchDir dir;
  PlainFile file(dir.path() / "anchor.log");
  const std::string after = live::audit_line(live::after_record_payload(typical_swap(1), live::AfterState::final));
  const std::string swap = live::audit_line(live::swap_record_payload(typical_swap(2)));
  time_appends(state, [&](int) {
    file.write(after, false);
    file.write(swap, true);
  });
}

void BM_SwapAuditAppendAfterFollowing(benchmark::State& state) {
  ScratchDir dir;
  live::SwapAuditFile file(dir.path());
  const live::SwapEntry entry = typical_swap(1);
  state.counters["line_bytes"] = static_cast<double>(
      live::audit_line(live::after_record_payload(entry, live::AfterState::following)).size());
  time_appends(state, [&](int) { file.append_after(entry, live::AfterState::following, false); });
}

void BM_AnchorWriteOfTheSameBytes(benchmark::State& state) {
  ScratchDir dir;
  PlainFile file(dir.path() / "anchor.log");
  const std::string line = live::audit_line(live::after_record_payload(typical_swap(1), live::AfterState::following));
  time_appends(state, [&](int) { file.write(line, false); });
}

BENCHMARK(BM_SwapAuditAddSwap)->Iterations(kAppends)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_AnchorWriteWriteFdatasyncOfTheSameBytes)->Iterations(kAppends)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_SwapAuditAppendAfterFollowing)->Iterations(kAppends)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_AnchorWriteOfTheSameBytes)->Iterations(kAppends)->Unit(benchmark::kMicrosecond);

}  // namespace
}  // namespace gc

BENCHMARK_MAIN();
