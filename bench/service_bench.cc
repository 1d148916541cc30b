// Round-trip latency and throughput of gearcoupling-service (docs/benchmarks.md, "Service").
// Runs against a service already started on --domain (bench/service_bench.sh starts one, and
// ddsperf ping/pong on the same configuration for the floor).
//
//   service_bench --domain N [--latency-requests 5000] [--latency-seconds S] [--modes call,call_then]
//                 [--seconds 3] [--clients 1,8,32] [--window 64] [--client-id-prefix HEX8]
//
// Latency: one client, one blocking call at a time, jam-angle then induced-moments requests
// (catalogue coupling nrel_upwind); p50/p99/mean of the round trip. Throughput: K clients (each
// its own participant and reply partition, one thread each) keeping --window induced-moments
// requests in flight for --seconds; completed replies per second. Every loop is bounded in
// count and time. Listener mode (jam_angle_cb, moments_cb): the same latency with call_then, each
// reply's callback sending the next request, as ddsperf's ping does. --latency-seconds S bounds
// each latency run by time instead (S seconds, as long as a ddsperf window: bench/service_bench.sh
// alternates short runs of both); --modes picks blocking calls (call), listener mode (call_then)
// or both.
#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <future>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "client/client.h"

namespace {

using gc::protocol::Calculation;
using gc::protocol::CatalogueName;
using Clock = std::chrono::steady_clock;

struct Options {
  int domain = 0;
  int latency_requests = 5000;
  double latency_seconds = 0.0;  ///< > 0: each latency run lasts this long (s), at most 1e6 requests
  bool blocking_calls = true;    ///< --modes has call
  bool listener_calls = true;    ///< --modes has call_then
  double seconds = 3.0;
  std::vector<int> clients = {1, 8, 32};
  std::size_t window = 64;
  std::uint32_t client_id_prefix = 0;  ///< with DDS Security: the identity's (bench/secure_bench.sh)
};

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string flag = argv[i];
    const std::string value = argv[i + 1];
    if (flag == "--domain") o.domain = std::atoi(value.c_str());
    else if (flag == "--latency-requests") o.latency_requests = std::atoi(value.c_str());
    else if (flag == "--latency-seconds") o.latency_seconds = std::atof(value.c_str());
    else if (flag == "--modes") {
      o.blocking_calls = o.listener_calls = false;
      std::stringstream list(value);
      for (std::string item; std::getline(list, item, ',');) {
        if (item == "call") o.blocking_calls = true;
        else if (item == "call_then") o.listener_calls = true;
        else {
          std::fprintf(stderr, "--modes: unknown mode \"%s\" (allowed: call, call_then)\n", item.c_str());
          std::exit(2);
        }
      }
    }
    else if (flag == "--seconds") o.seconds = std::atof(value.c_str());
    else if (flag == "--client-id-prefix") o.client_id_prefix = static_cast<std::uint32_t>(std::strtoul(value.c_str(), nullptr, 16));
    else if (flag == "--window") o.window = static_cast<std::size_t>(std::atoi(value.c_str()));
    else if (flag == "--clients") {
      o.clients.clear();
      std::stringstream list(value);
      for (std::string item; std::getline(list, item, ',');) o.clients.push_back(std::atoi(item.c_str()));
    } else {
      std::fprintf(stderr, "unknown flag %s\n", flag.c_str());
      std::exit(2);
    }
  }
  return o;
}

double percentile(std::vector<double> v, double p) {
  std::sort(v.begin(), v.end());
  const auto rank = static_cast<std::size_t>(p * static_cast<double>(v.size()));
  return v[std::min(rank, v.size() - 1)];
}

/// How long one latency run lasts: `count` requests or `length`, whichever comes first.
struct Bound {
  int count;
  Clock::duration length;
};

const gc::OperatingPoint kPoint{1.5e6, 0.007, 0.0, 0.1};

template <Calculation kCalculation, typename Request>
void latency(gc::client::Client& client, const char* name, const Request& request,
             const Bound& bound) {
  for (int i = 0; i < 200; ++i) client.call<kCalculation>(request);  // warm up
  std::vector<double> us;
  us.reserve(static_cast<std::size_t>(std::min(bound.count, 200000)));
  const Clock::time_point stop = Clock::now() + bound.length;
  for (int i = 0; i < bound.count && Clock::now() < stop; ++i) {
    const Clock::time_point start = Clock::now();
    client.call<kCalculation>(request);
    us.push_back(std::chrono::duration<double, std::micro>(Clock::now() - start).count());
  }
  double mean = 0.0;
  for (double x : us) mean += x / static_cast<double>(us.size());
  std::printf("latency %-16s n=%zu p50=%.1fus p99=%.1fus mean=%.1fus\n", name, us.size(),
              percentile(us, 0.50), percentile(us, 0.99), mean);
}

// The same round trip in listener mode, as ddsperf's ping measures it: each reply's callback
// (call_then, in Cyclone's receive thread) takes the time and sends the next request, so no
// thread of the client is woken in between.
template <Calculation kCalculation, typename Request>
void latency_in_listener(gc::client::Client& client, const char* name, const Request& request,
                         const Bound& bound) {
  std::vector<double> us;
  us.reserve(static_cast<std::size_t>(std::min(bound.count, 200000)));
  std::promise<std::string> done;  // "" or the error that stopped the run
  const Clock::time_point stop = Clock::now() + bound.length;
  Clock::time_point start;
  gc::client::Client::Callback<kCalculation> on_reply = [&](auto outcome) {
    if (outcome.error) {
      try {
        std::rethrow_exception(outcome.error);
      } catch (const std::exception& e) {
        done.set_value(e.what());
      }
      return;
    }
    us.push_back(std::chrono::duration<double, std::micro>(Clock::now() - start).count());
    if (static_cast<int>(us.size()) == bound.count || Clock::now() >= stop) {
      done.set_value("");
      return;
    }
    start = Clock::now();
    client.call_then<kCalculation>(request, on_reply);
  };
  std::future<std::string> finished = done.get_future();
  start = Clock::now();
  client.call_then<kCalculation>(request, on_reply);
  const std::string error = finished.get();
  if (!error.empty()) {
    std::fprintf(stderr, "%s in listener mode failed: %s\n", name, error.c_str());
    std::exit(1);
  }
  double mean = 0.0;
  for (double x : us) mean += x / static_cast<double>(us.size());
  std::printf("latency %-16s n=%zu p50=%.1fus p99=%.1fus mean=%.1fus (listener mode)\n", name,
              us.size(), percentile(us, 0.50), percentile(us, 0.99), mean);
}

void throughput(const Options& o, int clients) {
  std::vector<std::unique_ptr<gc::client::Client>> pool;
  for (int c = 0; c < clients; ++c) {
    pool.push_back(std::make_unique<gc::client::Client>(
        gc::client::ClientOptions{o.domain, std::chrono::seconds(30), o.client_id_prefix}));
  }
  for (auto& client : pool) {
    if (!client->wait_for_service(Calculation::kInducedMoments, std::chrono::seconds(20))) {
      std::fprintf(stderr, "no service on domain %d\n", o.domain);
      std::exit(1);
    }
  }
  std::atomic<long> completed{0};
  std::atomic<bool> measuring{false};
  std::atomic<bool> stop{false};
  std::vector<std::thread> threads;
  for (int c = 0; c < clients; ++c) {
    threads.emplace_back([&, c] {
      gc::client::Client& client = *pool[static_cast<std::size_t>(c)];
      std::deque<std::future<gc::InducedMoments>> in_flight;
      const gc::protocol::InducedMomentsRequest request{CatalogueName{"nrel_upwind"}, kPoint, {}};
      while (!stop) {
        while (in_flight.size() < o.window) {
          in_flight.push_back(client.call_async<Calculation::kInducedMoments>(request));
        }
        in_flight.front().get();
        in_flight.pop_front();
        if (measuring) completed.fetch_add(1, std::memory_order_relaxed);
      }
      while (!in_flight.empty()) {
        in_flight.front().get();
        in_flight.pop_front();
      }
    });
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(500));  // ramp up
  const Clock::time_point start = Clock::now();
  measuring = true;
  std::this_thread::sleep_for(std::chrono::duration<double>(o.seconds));
  measuring = false;
  const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
  stop = true;
  for (std::thread& thread : threads) thread.join();
  std::printf("throughput clients=%-3d window=%zu %.0f req/s (%ld replies in %.2f s)\n", clients,
              o.window, static_cast<double>(completed) / elapsed, completed.load(), elapsed);
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  {
    gc::client::Client client({o.domain, std::chrono::seconds(30), o.client_id_prefix});
    if (!client.wait_for_service(Calculation::kJamAngle, std::chrono::seconds(20))) {
      std::fprintf(stderr, "no service on domain %d\n", o.domain);
      return 1;
    }
    const Bound bound = o.latency_seconds > 0
                            ? Bound{1000000, std::chrono::duration_cast<Clock::duration>(
                                                 std::chrono::duration<double>(o.latency_seconds))}
                            : Bound{o.latency_requests, std::chrono::seconds(30)};
    const gc::protocol::JamAngleRequest jam{CatalogueName{"nrel_upwind"}};
    const gc::protocol::InducedMomentsRequest moments{CatalogueName{"nrel_upwind"}, kPoint, {}};
    if (o.blocking_calls) {
      latency<Calculation::kJamAngle>(client, "jam_angle", jam, bound);
      latency<Calculation::kInducedMoments>(client, "induced_moments", moments, bound);
    }
    if (o.listener_calls) {
      latency_in_listener<Calculation::kJamAngle>(client, "jam_angle_cb", jam, bound);
      latency_in_listener<Calculation::kInducedMoments>(client, "moments_cb", moments, bound);
    }
  }
  for (int clients : o.clients) throughput(o, clients);
  return 0;
}
