// A control loop against gearcoupling-service (bench/control_loop.sh, docs/benchmarks.md,
// "A control loop at 1 kHz"): one request at each tick of a fixed rate, each awaited before the
// next tick, for a fixed time. Writes one line per request, "T_S ROUND_TRIP_US" (T_S: when it
// was sent, CLOCK_MONOTONIC seconds, as perf timestamps are), to --out; bench/latency_stats.py
// turns the file into p50, p99, p99.9, the maximum and the share over 1 ms, as it does with
// ddsperf's round trips (bench/ddsperf_roundtrips.c).
//
//   gc_bench_control_loop --domain N --mode call|call_then [--rate-hz 1000] [--seconds 5]
//                         [--spin-us 0] [--phase-of FILE [--phase 0.5]] --out FILE
//
// call: the loop's thread makes a blocking call() (it sleeps until the reply wakes it, the
// wake-ups of ddsperf's waitset mode; with --spin-us, ClientOptions::spin_before_sleep, it
// spins that long on the reply before it sleeps). call_then: the loop's thread sends with
// call_then and the reply's callback, in Cyclone's receive thread, takes the time (ddsperf's
// listener mode, where ping's main thread sends at the rate and the listener takes the pong);
// the loop's thread waits for it only at the next tick, so no wake-up of its own lies inside
// the round trip.
// A tick missed because the previous request was still out is skipped, not made up (counted:
// missed_ticks). The request: induced moments of nrel_upwind at 1.5 MN m, 0.4 deg, mu 0.1.
//
// --phase-of FILE: the ticks fall --phase of a period after the sends of another sender at the
// same rate (PhaseLock), whose latest send FILE holds: ddsperf ping's, run beside the loop
// (bench/ddsperf_roundtrips.c's GC_DDSPERF_PING_TIMES). Two fixed-rate loops started side by
// side keep, through a whole run, the offset their starts happened to give, and the one whose
// round trip follows the other's closely finds the host's network path and caches warm: at
// 100 Hz with a hog per core, 0.6 x the other's median when it followed by 0.1-1.2 ms, 1.4 x when
// it led by 3 ms (docs/benchmarks.md). Half a period apart, neither follows the other closer.
#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include <CLI/CLI.hpp>

#include "client/client.h"

namespace {

using gc::protocol::Calculation;
using Clock = std::chrono::steady_clock;  // CLOCK_MONOTONIC in libstdc++

struct Options {
  int domain = 0;
  std::string mode = "call";
  double rate_hz = 1000.0;
  double seconds = 5.0;
  int spin_us = 0;
  std::string phase_of;  ///< holds the other sender's latest send (PhaseLock; empty: none)
  double phase = 0.5;    ///< ticks this many periods after the other sender's
  std::string out;
};

struct Sample {
  Clock::time_point sent;
  double round_trip_us;
};

/// Sleeps until `when` on CLOCK_MONOTONIC, an absolute time: no drift from the loop's own work.
void sleep_until(Clock::time_point when) {
  const auto ns = std::chrono::duration_cast<std::chrono::nanoseconds>(when.time_since_epoch());
  timespec t{static_cast<time_t>(ns.count() / 1000000000), static_cast<long>(ns.count() % 1000000000)};
  while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &t, nullptr) != 0) {
  }
}

/// Keeps the loop's ticks `phase` periods after the sends of another sender at the same rate,
/// whose latest send time a shared file holds (8 bytes: CLOCK_MONOTONIC ns; ddsperf ping's,
/// bench/ddsperf_roundtrips.c's GC_DDSPERF_PING_TIMES).
class PhaseLock {
 public:
  /// Maps `path`, waiting up to 20 s for a first send in it; check ok() after.
  PhaseLock(const std::string& path, Clock::duration period, double phase)
      : period_(period), offset_(std::chrono::duration_cast<Clock::duration>(period * phase)) {
    const Clock::time_point give_up = Clock::now() + std::chrono::seconds(20);
    while (latest_ == nullptr && Clock::now() < give_up) {
      map(path);
      if (latest_ == nullptr) std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    while (latest_ != nullptr && latest_send() == Clock::time_point() && Clock::now() < give_up) {
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    if (latest_ == nullptr || latest_send() == Clock::time_point()) {
      std::fprintf(stderr, "--phase-of %s: no send time in it within 20 s\n", path.c_str());
    } else {
      ok_ = true;
    }
  }
  ~PhaseLock() {
    if (latest_ != nullptr) munmap(const_cast<std::int64_t*>(latest_), sizeof(std::int64_t));
  }
  PhaseLock(const PhaseLock&) = delete;
  PhaseLock& operator=(const PhaseLock&) = delete;

  bool ok() const { return ok_; }

  /// The first tick, a period or more from now, `phase` periods after the other's schedule (a
  /// few of its sends looked at first: up to kSeen + 1 periods).
  Clock::time_point first() const {
    const Clock::time_point send = schedule();
    return at_or_after(Clock::now() + period_, send);
  }

  /// `tick`, or, once the other's sends have been over an eighth of a period off `phase` for
  /// kOffTicks ticks in a row (the other sender started its schedule again), the next tick after
  /// `now` on the other's new phase. One late send of the other's moves nothing.
  Clock::time_point follow(Clock::time_point tick, Clock::time_point now) {
    const Clock::duration off = folded((tick - latest_send() - offset_) % period_);
    off_ticks_ = (off > period_ / 8 || off < -period_ / 8) ? off_ticks_ + 1 : 0;
    if (off_ticks_ < kOffTicks) return tick;
    off_ticks_ = 0;
    moves_ += 1;
    return at_or_after(now + Clock::duration(1), latest_send());
  }
  /// How often follow() moved the ticks.
  long moves() const { return moves_; }

 private:
  static constexpr int kOffTicks = 3;
  static constexpr int kSeen = 5;

  void map(const std::string& path) {
    const int fd = open(path.c_str(), O_RDONLY);
    if (fd < 0) return;
    struct stat st{};
    if (fstat(fd, &st) == 0 && st.st_size >= static_cast<off_t>(sizeof(std::int64_t))) {
      void* p = mmap(nullptr, sizeof(std::int64_t), PROT_READ, MAP_SHARED, fd, 0);
      if (p != MAP_FAILED) latest_ = static_cast<const std::int64_t*>(p);
    }
    close(fd);
  }
  /// `off` (within a period either way) folded into half a period either way.
  Clock::duration folded(Clock::duration off) const {
    if (off > period_ / 2) return off - period_;
    if (off < -period_ / 2) return off + period_;
    return off;
  }
  /// The first tick at or after `earliest` that lies `phase` periods after `send` plus whole
  /// periods.
  Clock::time_point at_or_after(Clock::time_point earliest, Clock::time_point send) const {
    Clock::time_point tick = send + offset_;
    if (tick < earliest) {
      tick += (earliest - tick + period_ - Clock::duration(1)) / period_ * period_;
    }
    return tick;
  }
  /// A send of the other's on its schedule: of its next kSeen sends, the one least late against
  /// the first (a send is its tick plus the time its thread took to wake: one woken late would
  /// set the ticks off by that much).
  Clock::time_point schedule() const {
    const Clock::time_point first_seen = latest_send();
    Clock::time_point seen = first_seen;
    Clock::time_point earliest = first_seen;
    const Clock::time_point give_up = Clock::now() + (kSeen + 1) * period_;
    for (int n = 1; n < kSeen && Clock::now() < give_up;) {
      std::this_thread::sleep_for(period_ / 4);
      const Clock::time_point send = latest_send();
      if (send == seen) continue;
      seen = send;
      n += 1;
      const Clock::duration off = folded((send - first_seen) % period_);
      if (first_seen + off < earliest) earliest = first_seen + off;
    }
    return earliest;
  }
  Clock::time_point latest_send() const {
    return Clock::time_point(std::chrono::nanoseconds(__atomic_load_n(latest_, __ATOMIC_ACQUIRE)));
  }

  Clock::duration period_;
  Clock::duration offset_;  ///< phase x period
  const std::int64_t* latest_ = nullptr;
  bool ok_ = false;
  int off_ticks_ = 0;
  long moves_ = 0;
};

/// The round trip of one request, taken in the reply's callback (call_then): the loop's thread
/// waits for it only when it would send the next.
class Awaited {
 public:
  void start(Clock::time_point sent) {
    std::lock_guard lock(mutex_);
    sent_ = sent;
    done_ = false;
    failed_ = false;
  }
  void finish(bool failed) {
    const Clock::time_point now = Clock::now();
    {
      std::lock_guard lock(mutex_);
      round_trip_us_ = std::chrono::duration<double, std::micro>(now - sent_).count();
      failed_ = failed;
      done_ = true;
    }
    done_changed_.notify_one();
  }
  /// The round trip, or nullopt if the request failed.
  std::optional<double> wait() {
    std::unique_lock lock(mutex_);
    done_changed_.wait(lock, [this] { return done_; });
    return failed_ ? std::nullopt : std::optional<double>(round_trip_us_);
  }

 private:
  std::mutex mutex_;
  std::condition_variable done_changed_;
  Clock::time_point sent_;
  double round_trip_us_ = 0.0;
  bool done_ = true;
  bool failed_ = false;
};

struct Run {
  std::vector<Sample> samples;
  long missed_ticks = 0;
  long failed = 0;
  long phase_moves = 0;  ///< ticks moved onto the other sender's new phase (PhaseLock)
};

Clock::duration period_of(const Options& o) {
  return std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / o.rate_hz));
}

const gc::protocol::InducedMomentsRequest kRequest{
    gc::protocol::CatalogueName{"nrel_upwind"}, {1.5e6, 0.007, 0.0, 0.1}, {}};

/// Runs `request_at(sent)` at every tick of the rate for `o.seconds`; it returns the round trip
/// of the request before (or of this one, for call), or nullopt for a failed request.
template <typename RequestAt>
Run fixed_rate(const Options& o, PhaseLock* phase, RequestAt request_at) {
  Run run;
  const Clock::duration period = period_of(o);
  run.samples.reserve(static_cast<std::size_t>(o.rate_hz * o.seconds) + 1);
  const Clock::time_point start = phase != nullptr ? phase->first() : Clock::now() + period;
  const Clock::time_point stop =
      start + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(o.seconds));
  for (Clock::time_point tick = start; tick < stop;) {
    sleep_until(tick);
    request_at(Clock::now(), run);
    const Clock::time_point now = Clock::now();
    for (tick += period; tick <= now; tick += period) run.missed_ticks += 1;
    if (phase != nullptr) tick = phase->follow(tick, now);
  }
  if (phase != nullptr) run.phase_moves = phase->moves();
  return run;
}

Run blocking_calls(gc::client::Client& client, const Options& o, PhaseLock* phase) {
  return fixed_rate(o, phase, [&](Clock::time_point sent, Run& run) {
    try {
      client.call<Calculation::kInducedMoments>(kRequest);
      run.samples.push_back(
          {sent, std::chrono::duration<double, std::micro>(Clock::now() - sent).count()});
    } catch (const std::exception& e) {
      run.failed += 1;
      std::fprintf(stderr, "call failed: %s\n", e.what());
    }
  });
}

Run callbacks(gc::client::Client& client, const Options& o, PhaseLock* phase) {
  Awaited awaited;
  std::optional<Clock::time_point> previous;
  auto record_previous = [&](Run& run) {
    if (!previous) return;
    if (const std::optional<double> us = awaited.wait()) run.samples.push_back({*previous, *us});
    else run.failed += 1;
  };
  Run run = fixed_rate(o, phase, [&](Clock::time_point sent, Run& so_far) {
    record_previous(so_far);  // awaited: the previous reply is in before the next request goes out
    awaited.start(sent);
    previous = sent;
    client.call_then<Calculation::kInducedMoments>(
        kRequest, [&awaited](gc::client::Outcome<gc::InducedMoments> outcome) {
          awaited.finish(outcome.error != nullptr);
        });
  });
  record_previous(run);
  return run;
}

}  // namespace

int main(int argc, char** argv) {
  Options o;
  CLI::App app{"A fixed-rate control loop against gearcoupling-service (bench/control_loop.sh)"};
  app.add_option("--domain", o.domain, "DDS domain of the service")->required();
  app.add_option("--mode", o.mode, "call (blocking) or call_then (callback)")
      ->check(CLI::IsMember({"call", "call_then"}));
  app.add_option("--rate-hz", o.rate_hz, "requests per second")->check(CLI::Range(1.0, 20000.0));
  app.add_option("--seconds", o.seconds, "how long to run")->check(CLI::Range(0.1, 3600.0));
  app.add_option("--spin-us", o.spin_us, "call: spin this long on the reply before sleeping")
      ->check(CLI::Range(0, static_cast<int>(gc::client::kMaxSpinBeforeSleep.count())));
  app.add_option("--phase-of", o.phase_of,
                 "file holding the latest send of another sender at this rate (8 bytes, "
                 "CLOCK_MONOTONIC ns): tick --phase of a period after its sends");
  app.add_option("--phase", o.phase, "with --phase-of: periods after the other sender's sends")
      ->check(CLI::Range(0.0, 1.0));
  app.add_option("--out", o.out, "file for one \"T_S ROUND_TRIP_US\" line per request")->required();
  CLI11_PARSE(app, argc, argv);

  gc::client::ClientOptions client_options{o.domain, std::chrono::seconds(5)};
  client_options.spin_before_sleep = std::chrono::microseconds(o.spin_us);
  gc::client::Client client(client_options);
  if (!client.wait_for_service(Calculation::kInducedMoments, std::chrono::seconds(20))) {
    std::fprintf(stderr, "no service on domain %d\n", o.domain);
    return 1;
  }
  for (int i = 0; i < 200; ++i) client.call<Calculation::kInducedMoments>(kRequest);  // warm up
  std::optional<PhaseLock> phase;
  if (!o.phase_of.empty() && !phase.emplace(o.phase_of, period_of(o), o.phase).ok()) return 1;
  PhaseLock* locked = phase ? &*phase : nullptr;
  const Run run =
      o.mode == "call" ? blocking_calls(client, o, locked) : callbacks(client, o, locked);

  std::FILE* out = std::fopen(o.out.c_str(), "w");
  if (out == nullptr) {
    std::fprintf(stderr, "--out %s: cannot write\n", o.out.c_str());
    return 1;
  }
  for (const Sample& s : run.samples) {
    std::fprintf(out, "%.6f %.1f\n", std::chrono::duration<double>(s.sent.time_since_epoch()).count(),
                 s.round_trip_us);
  }
  std::fclose(out);
  char phase_text[32] = "free";
  if (phase) std::snprintf(phase_text, sizeof phase_text, "%g", o.phase);
  std::printf(
      "control_loop mode=%s rate_hz=%g spin_us=%d phase=%s phase_moves=%ld requests=%zu "
      "missed_ticks=%ld failed=%ld\n",
      o.mode.c_str(), o.rate_hz, o.spin_us, phase_text, run.phase_moves, run.samples.size(), run.missed_ticks, run.failed);
  return run.failed == 0 ? 0 : 1;
}
