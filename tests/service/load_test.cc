// Load: many clients at once and one client bursting. Every reply must come back to the client
// that asked, once, carrying the result of the request it answers (expected values: the core
// in process, compared bit for bit).
#include <signal.h>

#include <deque>
#include <future>
#include <thread>

#include <gtest/gtest.h>

#include "client/client.h"
#include "codec/coupling_catalog.h"
#include "tests/service/identical.h"
#include "tests/service/service_process.h"

namespace gc {
namespace {

using protocol::Calculation;
using protocol::CatalogueName;

/// A load case unique to (client, request), so a misdelivered reply cannot pass for the right one.
OperatingPoint unique_point(int client, int request) {
  return {1.0e5 + 1.0e3 * client + 0.5 * request, 0.005, 0.1 * (client % 7), 0.1};
}

TEST(Service, ThirtyTwoClientsThousandRequestsEachAllMatched) {
  constexpr int kClients = 32;
  constexpr int kRequests = 1000;
  constexpr std::size_t kWindow = 64;
  test::ServiceProcess service;
  const auto catalogue = codec::load_coupling_catalog(codec::default_catalog_dir());
  const CouplingGeometry& coupling = catalogue.at("nrel_downwind");

  std::vector<std::unique_ptr<client::Client>> clients;
  for (int c = 0; c < kClients; ++c) {
    clients.push_back(std::make_unique<client::Client>(
        client::ClientOptions{test::test_domain(), std::chrono::seconds(60)}));
  }
  std::vector<int> mismatches(kClients, 0);
  std::vector<int> answered(kClients, 0);
  std::vector<std::thread> threads;
  const auto started = std::chrono::steady_clock::now();
  for (int c = 0; c < kClients; ++c) {
    threads.emplace_back([&, c] {
      client::Client& client = *clients[c];
      std::deque<std::pair<int, std::future<InducedMoments>>> in_flight;
      const auto settle = [&] {
        auto& [request, future] = in_flight.front();
        const InducedMoments remote = future.get();
        const InducedMoments local = induced_moments(coupling, unique_point(c, request));
        if (test::bits(remote.magnitude_nm) != test::bits(local.magnitude_nm) ||
            test::bits(remote.direction_rad) != test::bits(local.direction_rad)) {
          ++mismatches[c];
        }
        ++answered[c];
        in_flight.pop_front();
      };
      for (int r = 0; r < kRequests; ++r) {
        if (in_flight.size() >= kWindow) settle();
        in_flight.emplace_back(r, client.call_async<Calculation::kInducedMoments>(
                                      {CatalogueName{"nrel_downwind"}, unique_point(c, r), {}}));
      }
      while (!in_flight.empty()) settle();
    });
  }
  for (std::thread& thread : threads) thread.join();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  std::cout << kClients * kRequests << " requests in " << seconds << " s ("
            << kClients * kRequests / seconds << " req/s)\n";
  for (int c = 0; c < kClients; ++c) {
    SCOPED_TRACE("client " + std::to_string(c));
    EXPECT_EQ(answered[c], kRequests);
    EXPECT_EQ(mismatches[c], 0);
    const client::ClientCounters counters = clients[c]->counters();
    EXPECT_EQ(counters.sent, static_cast<std::uint64_t>(kRequests));
    EXPECT_EQ(counters.replies, static_cast<std::uint64_t>(kRequests));
    EXPECT_EQ(counters.duplicates, 0u);
    EXPECT_EQ(counters.foreign, 0u);  // no other client's reply reached this one
    EXPECT_EQ(counters.timeouts, 0u);
  }
}

TEST(Service, OneClientBurstingTenThousandRequestsAllAnswered) {
  constexpr int kRequests = 10000;
  test::ServiceProcess service;
  client::Client client({test::test_domain(), std::chrono::seconds(60)});
  const auto catalogue = codec::load_coupling_catalog(codec::default_catalog_dir());
  std::vector<std::future<protocol::JamAngleResult>> futures;
  futures.reserve(kRequests);
  for (int r = 0; r < kRequests; ++r) {
    futures.push_back(client.call_async<Calculation::kJamAngle>(
        {CatalogueName{r % 2 == 0 ? "nrel_upwind" : "nrel_downwind"}}));
  }
  for (int r = 0; r < kRequests; ++r) {
    const JamAngle jam = futures[r].get().jam;
    const double expected =
        catalogue.at(r % 2 == 0 ? "nrel_upwind" : "nrel_downwind").jam_angle().angle_rad;
    ASSERT_EQ(test::bits(jam.angle_rad), test::bits(expected)) << "request " << r;
  }
  const client::ClientCounters counters = client.counters();
  EXPECT_EQ(counters.replies, static_cast<std::uint64_t>(kRequests));
  EXPECT_EQ(counters.duplicates, 0u);
  EXPECT_EQ(counters.resent, 0u);
}

// Protocol rule 9: a client keeps at most 256 requests in flight. With the instance stopped
// (SIGSTOP: nothing is answered), a thread calling 600 times gets 256 written, then waits for
// room; once the instance runs again every request is answered, in order of writing.
TEST(Service, AClientKeepsAtMost256RequestsInFlight) {
  constexpr int kRequests = 600;
  test::ServiceProcess service;
  client::Client client({test::test_domain(), std::chrono::seconds(30)});
  ASSERT_TRUE(client.wait_for_service(Calculation::kJamAngle, std::chrono::seconds(20)));
  ASSERT_TRUE(service.signal(SIGSTOP));
  std::vector<std::future<protocol::JamAngleResult>> futures(kRequests);
  std::thread caller([&] {
    for (auto& future : futures) {
      future = client.call_async<Calculation::kJamAngle>({CatalogueName{"nrel_upwind"}});
    }
  });
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (client.counters().sent < 256 && std::chrono::steady_clock::now() < give_up) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(300));  // would it write more?
  EXPECT_EQ(client.counters().sent, 256u);
  service.signal(SIGCONT);
  caller.join();
  for (auto& future : futures) EXPECT_NO_THROW(future.get());
  const client::ClientCounters counters = client.counters();
  EXPECT_EQ(counters.sent, static_cast<std::uint64_t>(kRequests));
  EXPECT_EQ(counters.replies, static_cast<std::uint64_t>(kRequests));
  EXPECT_EQ(counters.timeouts, 0u);
}

}  // namespace
}  // namespace gc
