// A control loop against gearcoupling-service (bench/control_loop.sh, docs/benchmarks.md,
// "A control loop at 1 kHz"): one request at each tick of a fixed rate, each awaited before the
// next tick, for a fixed time. Writes one line per request, "T_S ROUND_TRIP_US" (T_S: when it
// was sent, CLOCK_MONOTONIC seconds, as perf timestamps are), to --out; bench/latency_stats.py
// turns the file into p50, p99, p99.9, the maximum and the share over 1 ms, as it does with
// ddsperf's round trips (bench/ddsperf_roundtrips.c).
//
//   gc_bench_control_loop --domain N --mode call|call_then [--rate-hz 1000] [--seconds 5]
//                         [--spin-us 0] --out FILE
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
#include <time.h>

#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "clients/remote/client.h"

namespace {

using gc::protocol::Calculation;
using Clock = std::chrono::steady_clock;  // CLOCK_MONOTONIC in libstdc++

struct Options {
  int domain = 0;
  std::string mode = "call";
  double rate_hz = 1000.0;
  double seconds = 5.0;
  int spin_us = 0;
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
};

const gc::protocol::InducedMomentsRequest kRequest{
    gc::protocol::CatalogueName{"nrel_upwind"}, {1.5e6, 0.007, 0.0, 0.1}, {}};

/// Runs `request_at(sent)` at every tick of the rate for `o.seconds`; it returns the round trip
/// of the request before (or of this one, for call), or nullopt for a failed request.
template <typename RequestAt>
Run fixed_rate(const Options& o, RequestAt request_at) {
  Run run;
  const auto period = std::chrono::duration_cast<Clock::duration>(
      std::chrono::duration<double>(1.0 / o.rate_hz));
  run.samples.reserve(static_cast<std::size_t>(o.rate_hz * o.seconds) + 1);
  const Clock::time_point stop =
      Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(o.seconds));
  for (Clock::time_point tick = Clock::now() + period; tick < stop;) {
    sleep_until(tick);
    request_at(Clock::now(), run);
    const Clock::time_point now = Clock::now();
    for (tick += period; tick <= now; tick += period) run.missed_ticks += 1;
  }
  return run;
}

Run blocking_calls(gc::client::Client& client, const Options& o) {
  return fixed_rate(o, [&](Clock::time_point sent, Run& run) {
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

Run callbacks(gc::client::Client& client, const Options& o) {
  Awaited awaited;
  std::optional<Clock::time_point> previous;
  auto record_previous = [&](Run& run) {
    if (!previous) return;
    if (const std::optional<double> us = awaited.wait()) run.samples.push_back({*previous, *us});
    else run.failed += 1;
  };
  Run run = fixed_rate(o, [&](Clock::time_point sent, Run& so_far) {
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
  const Run run = o.mode == "call" ? blocking_calls(client, o) : callbacks(client, o);

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
  std::printf(
      "control_loop mode=%s rate_hz=%g spin_us=%d requests=%zu missed_ticks=%ld failed=%ld\n",
      o.mode.c_str(), o.rate_hz, o.spin_us, run.samples.size(), run.missed_ticks, run.failed);
  return run.failed == 0 ? 0 : 1;
}
