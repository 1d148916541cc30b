// The soak's load and its table (bench/soak.sh, docs/benchmarks.md "Soak"): --clients clients,
// each its own participant, each sending induced-moment requests at --rate-hz and awaiting each
// (call()), and one more client that joins the domain, is answered once and leaves again every
// --reconnect-period-s. Every --interval-s it prints a row: the interval's requests, failures and
// round-trip p50/p99, the reconnections made and failed, and the service's resident memory, open
// file descriptors and threads (from /proc/<--service-pid>). At the end it says whether the
// service stayed flat (below) and exits 1 if it did not or if any request failed.
//
//   gc_bench_soak --domain N --service-pid PID [--clients 8] [--rate-hz 100] [--seconds 3600]
//                 [--interval-s 60] [--reconnect-period-s 1] [--warmup-intervals N]
//
// Warm-up: the first tenth of the rows, and at least the first kMinWarmupS (--warmup-intervals
// to choose). Each client's reply writer in the service keeps up to 500 kB of replies not yet
// acknowledged (WhcHigh, deploy/cyclonedds-loopback.xml: acknowledgements are asked for only past
// 250 kB), 10-30 s of replies at 100 Hz, and the allocator's arenas grow with them for the first
// minutes; a leak goes on growing after that.
// Flat, after the warm-up intervals (the first row after them is the reference):
// - resident memory grows by at most kRssGrowthLimit over the reference, at every later row; in a
//   run shorter than kLongRunS, also by the reply windows (kReplyWindowMib per client, the
//   reconnecting one included), which may still fill after a short warm-up;
// - open file descriptors and threads are the reference's at every later row;
// - the median p99 of the later half of the rows is at most max(2 x, + 1 ms) that of the
//   earlier half (a slow leak or a growing queue shows there; one busy minute does not). Judged
//   from kP99MinRows rows on: over fewer (the 60 s run's five), one busy interval of this
//   shared machine moves a half's median by more than that.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "bench/percentile.h"
#include "client/client.h"

namespace {

using gc::bench::percentile;
using gc::protocol::Calculation;
using gc::protocol::CatalogueName;
using Clock = std::chrono::steady_clock;

constexpr double kRssGrowthLimit = 0.10;
constexpr double kP99Ratio = 2.0;
constexpr double kP99SlackUs = 1000.0;
constexpr std::size_t kP99MinRows = 10;
constexpr double kMinWarmupS = 30.0;
constexpr double kLongRunS = 600.0;
constexpr double kReplyWindowMib = 0.5;  ///< WhcHigh, 500 kB

struct Options {
  int domain = 0;
  int service_pid = 0;
  int clients = 8;
  double rate_hz = 100.0;
  double seconds = 3600.0;
  double interval_s = 60.0;
  double reconnect_period_s = 1.0;
  int warmup_intervals = -1;  ///< -1: a tenth of the rows, and at least kMinWarmupS
};

[[noreturn]] void usage_error(const std::string& message) {
  std::fprintf(stderr, "gc_bench_soak: %s\n", message.c_str());
  std::exit(2);
}

double in_range(const std::string& flag, const char* text, double low, double high) {
  char* end = nullptr;
  const double value = std::strtod(text, &end);
  if (end == text || *end != '\0' || !(value >= low && value <= high)) {
    usage_error(flag + " = " + text + " is outside [" + std::to_string(low) + ", " + std::to_string(high) + "]");
  }
  return value;
}

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i < argc; i += 2) {
    const std::string flag = argv[i];
    if (i + 1 >= argc) usage_error(flag + " needs a value");
    const char* v = argv[i + 1];
    if (flag == "--domain") o.domain = static_cast<int>(in_range(flag, v, 0, 230));
    else if (flag == "--service-pid") o.service_pid = static_cast<int>(in_range(flag, v, 1, 4194304));
    else if (flag == "--clients") o.clients = static_cast<int>(in_range(flag, v, 1, 64));
    else if (flag == "--rate-hz") o.rate_hz = in_range(flag, v, 0.1, 10000);
    else if (flag == "--seconds") o.seconds = in_range(flag, v, 1, 7 * 86400);
    else if (flag == "--interval-s") o.interval_s = in_range(flag, v, 1, 3600);
    else if (flag == "--reconnect-period-s") o.reconnect_period_s = in_range(flag, v, 0.1, 3600);
    else if (flag == "--warmup-intervals") o.warmup_intervals = static_cast<int>(in_range(flag, v, 0, 1000));
    else usage_error("unknown flag " + flag);
  }
  if (o.service_pid == 0) usage_error("--service-pid is required");
  if (o.warmup_intervals < 0) {
    const double rows = std::floor(o.seconds / o.interval_s + 1e-9);
    o.warmup_intervals = std::max({1, static_cast<int>(std::ceil(0.1 * rows)),
                                   static_cast<int>(std::ceil(kMinWarmupS / o.interval_s - 1e-9))});
  }
  return o;
}

/// What /proc says of the service.
struct ProcessSample {
  double rss_mib = NAN;
  long fds = -1;
  long threads = -1;
};

ProcessSample sample_process(int pid) {
  ProcessSample s;
  const std::string dir = "/proc/" + std::to_string(pid);
  std::ifstream status(dir + "/status");
  for (std::string line; std::getline(status, line);) {
    if (line.rfind("VmRSS:", 0) == 0) s.rss_mib = std::stod(line.substr(6)) / 1024.0;  // kB
    if (line.rfind("Threads:", 0) == 0) s.threads = std::stol(line.substr(8));
  }
  std::error_code error;
  long fds = 0;
  for (auto it = std::filesystem::directory_iterator(dir + "/fd", error); !error && it != std::filesystem::directory_iterator();
       it.increment(error)) {
    ++fds;
  }
  if (!error) s.fds = fds;
  return s;
}

/// Round trips and failures of the current interval, from every client thread.
class Interval {
 public:
  void answered(double round_trip_us) {
    std::lock_guard lock(mutex_);
    round_trips_us_.push_back(round_trip_us);
  }
  void failed(const std::string& why) {
    std::lock_guard lock(mutex_);
    if (failed_++ == 0) first_failure_ = why;
  }
  void reconnected(bool ok, double connect_ms) {
    std::lock_guard lock(mutex_);
    (ok ? reconnects_ : reconnects_failed_) += 1;
    if (ok) connects_ms_.push_back(connect_ms);
  }
  /// The interval's figures, and a new interval begun.
  struct Figures {
    std::vector<double> round_trips_us, connects_ms;
    long failed = 0, reconnects = 0, reconnects_failed = 0;
    std::string first_failure;
  };
  Figures take() {
    std::lock_guard lock(mutex_);
    Figures f{std::move(round_trips_us_), std::move(connects_ms_), failed_, reconnects_, reconnects_failed_,
              std::move(first_failure_)};
    round_trips_us_.clear();
    connects_ms_.clear();
    failed_ = reconnects_ = reconnects_failed_ = 0;
    first_failure_.clear();
    return f;
  }

 private:
  std::mutex mutex_;
  std::vector<double> round_trips_us_, connects_ms_;
  long failed_ = 0, reconnects_ = 0, reconnects_failed_ = 0;
  std::string first_failure_;
};

gc::protocol::InducedMomentsRequest request(std::uint64_t k) {
  return {CatalogueName{"nrel_upwind"}, {1.0e6 + static_cast<double>(k % 1000) * 1.0e3, 0.005, 0.0, 0.1}, {}};
}

/// One fixed-rate client until `stop`: a slot missed (a slow answer) is skipped, not made up.
void steady_client(const Options& o, const std::atomic<bool>& stop, Interval& interval) {
  gc::client::Client client({o.domain, std::chrono::seconds(5)});
  if (!client.wait_for_service(Calculation::kInducedMoments, std::chrono::seconds(20))) {
    interval.failed("no instance found in 20 s");
    return;
  }
  const auto period = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / o.rate_hz));
  const Clock::time_point start = Clock::now();
  for (std::uint64_t slot = 0, k = 0; !stop.load(); ++k) {
    std::this_thread::sleep_until(start + slot * period);
    const Clock::time_point sent = Clock::now();
    try {
      client.call<Calculation::kInducedMoments>(request(k));
      interval.answered(std::chrono::duration<double, std::micro>(Clock::now() - sent).count());
    } catch (const std::exception& e) {
      interval.failed(e.what());
    }
    slot = std::max<std::uint64_t>(slot + 1, static_cast<std::uint64_t>((Clock::now() - start) / period) + 1);
  }
}

/// A client that joins, is answered once and leaves, every reconnect period, until `stop`.
void reconnecting_client(const Options& o, const std::atomic<bool>& stop, Interval& interval) {
  const auto period = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(o.reconnect_period_s));
  for (Clock::time_point next = Clock::now(); !stop.load(); next += period) {
    std::this_thread::sleep_until(next);
    const Clock::time_point begun = Clock::now();
    bool ok = false;
    try {
      gc::client::Client client({o.domain, std::chrono::seconds(5)});
      client.call<Calculation::kJamAngle>({CatalogueName{"nrel_upwind"}});
      ok = true;
    } catch (const std::exception&) {
    }
    interval.reconnected(ok, std::chrono::duration<double, std::milli>(Clock::now() - begun).count());
    next = std::max(next, Clock::now() - period);  // a slow one does not make the next ones hurry
  }
}

struct Row {
  double t_s, p50_us, p99_us, rss_mib;
  long requests, failed, reconnects, reconnects_failed, fds, threads;
  double connect_p50_ms;
};

double median(std::vector<double> v) { return percentile(std::move(v), 0.5); }

/// Prints the verdict on `rows` (the warm-up ones excluded); true when flat. `rss_allowance_mib`:
/// RSS growth allowed besides kRssGrowthLimit.
bool flat(const std::vector<Row>& rows, int warmup, double rss_allowance_mib) {
  if (static_cast<int>(rows.size()) < warmup + 2) {
    std::printf("flat: too few rows after the warm-up (%zu rows, %d of warm-up) to judge\n", rows.size(), warmup);
    return false;
  }
  const Row& ref = rows[static_cast<std::size_t>(warmup)];
  double rss_max = ref.rss_mib;
  long fds_min = ref.fds, fds_max = ref.fds, threads_min = ref.threads, threads_max = ref.threads;
  std::vector<double> early, late;
  const std::size_t judged = rows.size() - static_cast<std::size_t>(warmup);
  for (std::size_t i = static_cast<std::size_t>(warmup); i < rows.size(); ++i) {
    const Row& r = rows[i];
    rss_max = std::max(rss_max, r.rss_mib);
    fds_min = std::min(fds_min, r.fds), fds_max = std::max(fds_max, r.fds);
    threads_min = std::min(threads_min, r.threads), threads_max = std::max(threads_max, r.threads);
    (i - static_cast<std::size_t>(warmup) < judged / 2 ? early : late).push_back(r.p99_us);
  }
  const double growth = rss_max / ref.rss_mib - 1.0;
  const double growth_limit = kRssGrowthLimit + rss_allowance_mib / ref.rss_mib;
  const double p99_early = median(early), p99_late = median(late);
  const double p99_limit = std::max(kP99Ratio * p99_early, p99_early + kP99SlackUs);
  const bool rss_ok = growth <= growth_limit;
  const bool fds_ok = fds_min == fds_max, threads_ok = threads_min == threads_max;
  const bool p99_judged = judged >= kP99MinRows;
  const bool p99_ok = !p99_judged || p99_late <= p99_limit;
  std::printf("flat: RSS %.1f MiB at the reference, at most %+.1f %% later (limit +%.0f %%%s): %s\n", ref.rss_mib,
              100.0 * growth, 100.0 * growth_limit, rss_allowance_mib > 0.0 ? ", with the reply windows" : "",
              rss_ok ? "yes" : "NO");
  std::printf("flat: file descriptors %ld..%ld (constant): %s\n", fds_min, fds_max, fds_ok ? "yes" : "NO");
  std::printf("flat: threads %ld..%ld (constant): %s\n", threads_min, threads_max, threads_ok ? "yes" : "NO");
  std::printf("flat: p99 median %.0f us in the earlier half, %.0f us in the later (limit %.0f us): %s\n", p99_early,
              p99_late, p99_limit, !p99_judged ? "not judged, fewer than 10 rows" : p99_ok ? "yes" : "NO");
  return rss_ok && fds_ok && threads_ok && p99_ok;
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  std::atomic<bool> stop{false};
  Interval interval;
  std::vector<std::thread> threads;
  for (int c = 0; c < o.clients; ++c) threads.emplace_back([&] { steady_client(o, stop, interval); });
  threads.emplace_back([&] { reconnecting_client(o, stop, interval); });

  std::printf("# %d clients at %.0f Hz each, awaiting each answer, and one client reconnecting every %.1f s, for %.0f s; "
              "a row every %.0f s (the first %d warm-up)\n",
              o.clients, o.rate_hz, o.reconnect_period_s, o.seconds, o.interval_s, o.warmup_intervals);
  std::printf("%7s %9s %6s %8s %8s %10s %8s %10s %8s %5s %7s\n", "t_s", "requests", "failed", "p50_us", "p99_us",
              "reconnects", "rc_fail", "connect_ms", "rss_mib", "fds", "threads");
  std::fflush(stdout);
  const Clock::time_point start = Clock::now();
  const auto rows_wanted = static_cast<int>(std::floor(o.seconds / o.interval_s + 1e-9));
  std::vector<Row> rows;
  long failed_total = 0;
  std::string first_failure;
  for (int i = 1; i <= rows_wanted; ++i) {
    std::this_thread::sleep_until(start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(i * o.interval_s)));
    Interval::Figures f = interval.take();
    const ProcessSample p = sample_process(o.service_pid);
    const Row row{i * o.interval_s, percentile(f.round_trips_us, 0.5), percentile(f.round_trips_us, 0.99), p.rss_mib,
                  static_cast<long>(f.round_trips_us.size()), f.failed, f.reconnects, f.reconnects_failed, p.fds,
                  p.threads, percentile(f.connects_ms, 0.5)};
    rows.push_back(row);
    failed_total += f.failed;
    if (first_failure.empty()) first_failure = f.first_failure;
    std::printf("%7.0f %9ld %6ld %8.0f %8.0f %10ld %8ld %10.1f %8.1f %5ld %7ld\n", row.t_s, row.requests, row.failed,
                row.p50_us, row.p99_us, row.reconnects, row.reconnects_failed, row.connect_p50_ms, row.rss_mib, row.fds,
                row.threads);
    std::fflush(stdout);
  }
  stop.store(true);
  for (std::thread& t : threads) t.join();
  const double rss_allowance_mib = o.seconds < kLongRunS ? kReplyWindowMib * (o.clients + 1) : 0.0;
  const bool is_flat = flat(rows, o.warmup_intervals, rss_allowance_mib);
  long reconnects_failed = 0;
  for (const Row& r : rows) reconnects_failed += r.reconnects_failed;
  if (failed_total > 0) std::printf("failed requests: %ld, the first: %s\n", failed_total, first_failure.c_str());
  if (reconnects_failed > 0) std::printf("failed reconnections: %ld\n", reconnects_failed);
  const bool pass = is_flat && failed_total == 0 && reconnects_failed == 0;
  std::printf("soak: %s\n", pass ? "PASS" : "FAIL");
  return pass ? 0 : 1;
}
