// Failures around the service: it is killed and restarted, one of two instances is killed, a
// client dies mid-request, the service is asked to stop with requests in flight.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <deque>
#include <future>
#include <thread>

#include <gtest/gtest.h>

#include "client/client.h"
#include "codec/coupling_catalog.h"
#include "protocol/matching.h"
#include "tests/service/identical.h"
#include "tests/service/service_process.h"

namespace gc {
namespace {

using protocol::Calculation;
using protocol::CatalogueName;
using Clock = std::chrono::steady_clock;

const protocol::JamAngleRequest kJam{CatalogueName{"nrel_upwind"}};

TEST(Service, KilledAndRestartedClientsTimeOutThenCarryOn) {
  client::Client client({test::test_domain(), std::chrono::milliseconds(1000)});
  auto first = std::make_unique<test::ServiceProcess>();
  ASSERT_TRUE(client.wait_for_service(Calculation::kJamAngle, std::chrono::seconds(10)));
  EXPECT_NO_THROW(client.call<Calculation::kJamAngle>(kJam));

  first->signal(SIGKILL);
  first.reset();
  EXPECT_THROW(client.call<Calculation::kJamAngle>(kJam), client::Timeout);

  test::ServiceProcess second;
  // The same client object carries on: once the new instance is found, calls succeed again.
  const Clock::time_point give_up = Clock::now() + std::chrono::seconds(15);
  int timeouts_while_recovering = 0;
  for (;;) {
    try {
      client.call<Calculation::kJamAngle>(kJam);
      break;
    } catch (const client::Timeout&) {
      ++timeouts_while_recovering;
      ASSERT_LT(Clock::now(), give_up) << "never recovered";
    }
  }
  for (int r = 0; r < 50; ++r) EXPECT_NO_THROW(client.call<Calculation::kJamAngle>(kJam));
  EXPECT_GE(client.counters().timeouts, 1u);
  std::cout << "timeouts while the dead instance was still believed alive: "
            << timeouts_while_recovering << "\n";
}

// The client's receive loop sleeps until the next deadline it knows of (at most 1 s): a request
// whose deadline comes sooner wakes it, so it times out on time, not at the loop's next look.
TEST(Service, AnUnansweredRequestTimesOutOnTimeWhileTheClientsLoopSleeps) {
  test::ServiceProcess service;
  client::Client client({test::test_domain(), std::chrono::milliseconds(150)});
  ASSERT_TRUE(client.wait_for_service(Calculation::kJamAngle, std::chrono::seconds(10)));
  EXPECT_NO_THROW(client.call<Calculation::kJamAngle>(kJam));
  // The loop last looked when that reply came; it now sleeps until about 1 s later.
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  ASSERT_TRUE(service.signal(SIGSTOP));  // returns once the instance has stopped
  const Clock::time_point start = Clock::now();
  EXPECT_THROW(client.call<Calculation::kJamAngle>(kJam), client::Timeout);
  const double elapsed_s = std::chrono::duration<double>(Clock::now() - start).count();
  service.signal(SIGCONT);
  EXPECT_GE(elapsed_s, 0.15);
  EXPECT_LT(elapsed_s, 0.5) << "the timeout waited for the receive loop's idle wake-up";
}

OperatingPoint unique_point(int request) { return {1.0e5 + 10.0 * request, 0.005, 0.3, 0.1}; }

TEST(Service, TwoInstancesOneKilledMidRunEveryRequestAnsweredExactlyOnce) {
  constexpr int kRequests = 4000;
  constexpr std::size_t kWindow = 64;
  const auto catalogue = codec::load_coupling_catalog(codec::default_catalog_dir());
  const CouplingGeometry& coupling = catalogue.at("nrel_downwind");
  test::ServiceProcess a;
  test::ServiceProcess b;
  client::Client client({test::test_domain(), std::chrono::seconds(30)});
  ASSERT_TRUE(protocol::wait_until([&] { return client.instances().size() == 2; },
                                   Clock::now() + std::chrono::seconds(10)));

  std::deque<std::pair<int, std::future<InducedMoments>>> in_flight;
  int answered = 0;
  int wrong = 0;
  bool killed = false;
  for (int r = 0; r < kRequests || !in_flight.empty();) {
    if (r < kRequests && in_flight.size() < kWindow) {
      in_flight.emplace_back(r, client.call_async<Calculation::kInducedMoments>(
                                    {CatalogueName{"nrel_downwind"}, unique_point(r), {}}));
      ++r;
      continue;
    }
    auto& [request, future] = in_flight.front();
    const InducedMoments remote = future.get();
    wrong += test::bits(remote.magnitude_nm) !=
             test::bits(induced_moments(coupling, unique_point(request)).magnitude_nm);
    ++answered;
    in_flight.pop_front();
    if (!killed && answered == kRequests / 3) {
      a.signal(SIGKILL);
      killed = true;
    }
  }
  EXPECT_EQ(answered, kRequests);
  EXPECT_EQ(wrong, 0);
  const client::ClientCounters counters = client.counters();
  EXPECT_EQ(counters.replies, static_cast<std::uint64_t>(kRequests));
  EXPECT_EQ(counters.duplicates, 0u);
  EXPECT_EQ(counters.timeouts, 0u);
  EXPECT_GT(counters.resent, 0u);  // the killed instance's unanswered requests went to the other
  EXPECT_EQ(counters.sent, kRequests + counters.resent);
  EXPECT_EQ(client.instances().size(), 1u);
  std::cout << "resent after the kill: " << counters.resent << "\n";
}

TEST(Service, ClientDyingMidRequestLeavesTheServiceHealthy) {
  test::ServiceProcess service;
  client::Client client({test::test_domain(), std::chrono::seconds(5)});
  ASSERT_TRUE(client.wait_for_service(Calculation::kJamAngle, std::chrono::seconds(10)));
  const std::string domain = std::to_string(test::test_domain());  // before fork: pid-based
  for (int round = 0; round < 2; ++round) {
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      execl(GC_ABRUPT_CLIENT_BINARY, GC_ABRUPT_CLIENT_BINARY, domain.c_str(), "500",
            static_cast<char*>(nullptr));
      _exit(127);
    }
    int status = 0;
    waitpid(child, &status, 0);
    ASSERT_TRUE(WIFEXITED(status));
    ASSERT_EQ(WEXITSTATUS(status), 0);
  }
  // The service answers everyone else without waiting for the dead client's lease to expire.
  const Clock::time_point started = Clock::now();
  for (int r = 0; r < 200; ++r) EXPECT_NO_THROW(client.call<Calculation::kJamAngle>(kJam));
  const double seconds = std::chrono::duration<double>(Clock::now() - started).count();
  EXPECT_LT(seconds, 3.0);
  EXPECT_TRUE(service.running());
  std::cout << "200 calls after two clients died mid-request: " << seconds << " s\n";
}

TEST(Service, SigtermAnswersRequestsInFlightThenExitsCleanly) {
  constexpr int kRequests = 3000;
  test::ServiceProcess service;
  client::Client client({test::test_domain(), std::chrono::seconds(10)});
  ASSERT_TRUE(client.wait_for_service(Calculation::kInducedMoments, std::chrono::seconds(10)));
  std::vector<std::future<InducedMoments>> futures;
  for (int r = 0; r < kRequests; ++r) {
    futures.push_back(client.call_async<Calculation::kInducedMoments>(
        {CatalogueName{"nrel_downwind"}, unique_point(r), {}}));
  }
  service.signal(SIGTERM);
  int ok = 0;
  for (auto& future : futures) {
    try {
      future.get();
      ++ok;
    } catch (const std::exception& e) {
      ADD_FAILURE() << e.what();
      break;
    }
  }
  EXPECT_EQ(ok, kRequests);
  EXPECT_EQ(service.wait_exit(10.0), 0);
}

}  // namespace
}  // namespace gc
