// Several hosts (issue 9): three network namespaces joined by a bridge, addressed in 198.18.0.0/15
// (tests/service/test_network.h), with the LAN configuration's real multicast discovery instead
// of loopback. Two service instances run on two "hosts", a client on the third;
// one instance is killed mid-run and every request must still be answered exactly once, by the
// other. Needs root (ip netns); skipped with a message otherwise. The namespaces and everything
// in them are removed when the test ends.
#include <signal.h>

#include <deque>
#include <functional>
#include <future>
#include <iostream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "client/client.h"
#include "codec/coupling_catalog.h"
#include "core/induced_moments.h"
#include "protocol/matching.h"
#include "tests/service/client_on_host.h"
#include "tests/service/identical.h"
#include "tests/service/secure_cell.h"
#include "tests/service/service_process.h"
#include "tests/service/test_network.h"

namespace gc {
namespace {

using protocol::Calculation;
using protocol::CatalogueName;
using Clock = std::chrono::steady_clock;
using test::ClientOnHost;
using test::TestNetwork;

OperatingPoint unique_point(int request) { return {1.0e5 + 10.0 * request, 0.005, 0.3, 0.1}; }

constexpr const char* kLanMulticast = "file://" GC_SOURCE_DIR "/deploy/cyclonedds-lan-multicast.xml";

/// What the client on host 3 saw.
struct ClientReport {
  std::size_t instances_at_start = 0;
  int answered = 0, wrong = 0, failed = 0;
  client::ClientCounters counters;
};

constexpr int kRequests = 1500;
constexpr std::size_t kWindow = 32;
constexpr int kKillAfter = kRequests / 3;

/// kRequests induced-moment requests, kWindow in flight, each checked against the core's value;
/// says "kill" when a third are answered.
std::string requests_with_a_kill(int domain, const std::function<void(const std::string&)>& say) {
  const auto catalogue = codec::load_coupling_catalog(codec::default_catalog_dir());
  const CouplingGeometry& coupling = catalogue.at("nrel_downwind");
  client::Client client({domain, std::chrono::seconds(20)});
  ClientReport r;
  protocol::wait_until([&] { return client.instances().size() == 2; }, Clock::now() + std::chrono::seconds(20));
  r.instances_at_start = client.instances().size();
  std::deque<std::pair<int, std::future<InducedMoments>>> in_flight;
  for (int sent = 0; sent < kRequests || !in_flight.empty();) {
    if (sent < kRequests && in_flight.size() < kWindow) {
      in_flight.emplace_back(sent, client.call_async<Calculation::kInducedMoments>(
                                       {CatalogueName{"nrel_downwind"}, unique_point(sent), {}}));
      ++sent;
      continue;
    }
    auto& [request, future] = in_flight.front();
    try {
      const InducedMoments remote = future.get();
      r.wrong += test::bits(remote.magnitude_nm) != test::bits(induced_moments(coupling, unique_point(request)).magnitude_nm);
      ++r.answered;
    } catch (const std::exception& e) {
      if (r.failed++ == 0) say(std::string("failure ") + e.what());
    }
    in_flight.pop_front();
    if (r.answered == kKillAfter) say("kill");
  }
  r.counters = client.counters();
  std::ostringstream line;
  line << "report " << r.instances_at_start << " " << r.answered << " " << r.wrong << " " << r.failed << " "
       << r.counters.sent << " " << r.counters.replies << " " << r.counters.resent << " " << r.counters.duplicates
       << " " << r.counters.timeouts << " " << r.counters.foreign;
  return line.str();
}

TEST(MultiHost, TwoInstancesOnTwoHostsOneKilledEveryRequestAnsweredExactlyOnceOnTheThird) {
  const TestNetwork network;
  if (!network.why_not().empty()) GTEST_SKIP() << network.why_not();
  setenv("CYCLONEDDS_URI", kLanMulticast, 1);
  const int domain = test::test_domain();
  test::ServiceProcess a({}, {}, {}, network.host(1));
  test::ServiceProcess b({}, {}, {}, network.host(2));
  ClientOnHost client(network.host(3), {}, [domain](const ClientOnHost::Say& say) { return requests_with_a_kill(domain, say); });

  std::string line = client.line(std::chrono::seconds(60));
  EXPECT_EQ(line, "kill") << "the client never got a third of its answers";
  if (line == "kill") {
    a.signal(SIGKILL);
    line = client.line(std::chrono::seconds(90));
  }
  std::istringstream report(line);
  std::string word;
  ClientReport r;
  report >> word >> r.instances_at_start >> r.answered >> r.wrong >> r.failed >> r.counters.sent >> r.counters.replies >>
      r.counters.resent >> r.counters.duplicates >> r.counters.timeouts >> r.counters.foreign;
  ASSERT_EQ(word, "report") << "the client said \"" << line << "\"";
  EXPECT_EQ(r.instances_at_start, 2u) << "both instances discovered across the bridge by multicast";
  EXPECT_EQ(r.answered, kRequests);
  EXPECT_EQ(r.failed, 0);
  EXPECT_EQ(r.wrong, 0);
  EXPECT_EQ(r.counters.replies, static_cast<std::uint64_t>(kRequests)) << "each request answered once";
  EXPECT_EQ(r.counters.duplicates, 0u);
  EXPECT_EQ(r.counters.foreign, 0u);
  EXPECT_EQ(r.counters.timeouts, 0u);
  EXPECT_GT(r.counters.resent, 0u) << "the killed instance's unanswered requests went to the other host";
  EXPECT_EQ(r.counters.sent, kRequests + r.counters.resent);
  EXPECT_TRUE(b.running());
  std::cout << "across hosts: " << kRequests << " requests, " << r.counters.resent
            << " resent to host 2 after host 1's instance was killed\n";
}

/// How many of `calls` jam-angle calls a client with `options` gets answered, after waiting up
/// to `discovery` for an instance: "answered <n> instances <m>".
std::string jam_angle_calls(client::ClientOptions options, int calls, std::chrono::seconds discovery) {
  client::Client client(options);
  const bool found = client.wait_for_service(Calculation::kJamAngle, discovery);
  int answered = 0;
  for (int c = 0; found && c < calls; ++c) {
    try {
      client.call<Calculation::kJamAngle>({CatalogueName{"nrel_upwind"}});
      ++answered;
    } catch (const std::exception&) {
    }
  }
  return "answered " + std::to_string(answered) + " instances " + std::to_string(client.instances().size());
}

// The secure configuration across hosts: the service on host 1 and a client with its certificate
// on host 3 talk over the bridge, authenticated and encrypted; a participant without
// certificates on host 2 finds no instance.
TEST(MultiHost, TheSecureConfigurationWorksAcrossHostsAndAStrangerOnTheLanSeesNothing) {
  if (!test::security_plugins_installed()) GTEST_SKIP() << "Cyclone's DDS Security plugins are not installed";
  const TestNetwork network;
  if (!network.why_not().empty()) GTEST_SKIP() << network.why_not();
  const test::SecureCell cell;
  const int domain = test::test_domain();
  test::ServiceProcess service({}, {}, {{"CYCLONEDDS_URI", cell.uri("service-main", kLanMulticast)}}, network.host(1));

  client::ClientOptions secure{domain, std::chrono::seconds(10)};
  secure.client_id_prefix = cell.client_prefix("a");
  ClientOnHost client(network.host(3), {{"CYCLONEDDS_URI", cell.uri("client-a", kLanMulticast)}},
                      [secure](const ClientOnHost::Say&) { return jam_angle_calls(secure, 50, std::chrono::seconds(20)); });
  ClientOnHost stranger(network.host(2), {{"CYCLONEDDS_URI", kLanMulticast}}, [domain](const ClientOnHost::Say&) {
    return jam_angle_calls({domain, std::chrono::seconds(2)}, 5, std::chrono::seconds(8));
  });
  EXPECT_EQ(client.line(std::chrono::seconds(60)), "answered 50 instances 1");
  EXPECT_EQ(stranger.line(std::chrono::seconds(60)), "answered 0 instances 0");
  EXPECT_TRUE(service.running());
}

}  // namespace
}  // namespace gc
