// Network faults between hosts (issue 26): the three test hosts of test_network.h, each joined
// to the bridge by a user-space faulty link (faulty_link.cc; this kernel has no netem), with the
// LAN configuration's multicast discovery. A client on host 3 sends requests at a fixed rate
// (fixed_rate_run.h) under loss, delay with jitter, duplication and reordering; across a
// partition of its own host; and while one instance's host is cut off and the other serves.
// Every request must be answered exactly once with the core's own value, or fail at its caller
// with a timeout: never a duplicate, a wrong value, or a silent loss; after a heal the service
// answers again within 5 s. The counts and latencies are printed (docs/benchmarks.md, "Network
// faults between hosts"). Needs root; skipped with the reason otherwise.
#include <signal.h>

#include <array>
#include <chrono>
#include <cstdlib>
#include <iostream>
#include <map>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "tests/service/client_on_host.h"
#include "tests/service/fixed_rate_run.h"
#include "tests/service/link_faults.h"
#include "tests/service/service_process.h"
#include "tests/service/test_network.h"

namespace gc::test {
namespace {

using std::chrono::milliseconds;
using std::chrono::seconds;

constexpr const char* kLanMulticast = "file://" GC_SOURCE_DIR "/deploy/cyclonedds-lan-multicast.xml";

/// The faults of the issue: 10 % loss, 20 +- 10 ms delay, 1 % duplication and reordering.
constexpr LinkFaults kLossy{0.10, 0.020, 0.010, 0.01, 0.01};
constexpr LinkFaults kClean{};

constexpr int kClientHost = 3;
constexpr seconds kBeforePartition{3};

/// A host's link cut for a while, kBeforePartition after the run starts.
struct Cut {
  int host = 0;  ///< 0: none
  milliseconds length{0};
};

/// A client run on host 3 against instances on `service_hosts`, with `faults` per host; with
/// `cut`, that host's link is cut kBeforePartition after the run starts and healed `cut.length`
/// later. Returns the run's figures (empty when skipped) and prints them with the links' counts.
class FaultRun {
 public:
  explicit FaultRun(const std::array<LinkFaults, TestNetwork::kHosts>& faults) : network_(faults) {}

  const std::string& why_not() const { return network_.why_not(); }

  std::map<std::string, double> run(const std::vector<int>& service_hosts, RunPlan plan, Cut cut,
                                    const std::string& name) {
    setenv("CYCLONEDDS_URI", kLanMulticast, 1);
    plan.domain = test_domain();
    plan.instances = service_hosts.size();
    std::vector<std::unique_ptr<ServiceProcess>> services;
    for (int host : service_hosts) services.push_back(std::make_unique<ServiceProcess>(
        std::vector<std::string>{}, std::string{}, std::vector<std::pair<std::string, std::string>>{}, network_.host(host)));
    ClientOnHost client(network_.host(kClientHost), {}, [plan](const ClientOnHost::Say& say) { return fixed_rate_run(plan, say); });
    const std::string started = client.line(seconds(45));
    if (started != "running") {
      ADD_FAILURE() << name << ": the client did not start: \"" << started << "\"";
      return {};
    }
    if (cut.host != 0) {
      std::this_thread::sleep_for(kBeforePartition);
      network_.partition(cut.host);
      client.signal(SIGUSR2);
      std::this_thread::sleep_for(cut.length);
      client.signal(SIGUSR1);  // marked before the heal: the recovery measured is not shorter than it was
      network_.heal(cut.host);
    }
    const std::string line = client.line(milliseconds(static_cast<long>(1000 * plan.duration_s)) + plan.timeout + seconds(30));
    std::cout << name << ": " << line << "\n";
    for (int host = 1; host <= TestNetwork::kHosts; ++host) std::cout << network_.stop_link(host);
    for (auto& service : services) EXPECT_TRUE(service->running()) << name << ": an instance died";
    try {
      return parse_report(line);
    } catch (const std::exception& e) {
      ADD_FAILURE() << name << ": " << e.what();
      return {};
    }
  }

 private:
  TestNetwork network_;
};

/// Every request answered once with the right value or failed with a timeout at its caller.
void expect_each_request_answered_once_or_timed_out(std::map<std::string, double> r) {
  EXPECT_GT(r["requests"], 0);
  EXPECT_EQ(r["wrong"], 0) << "answers differing from the core's";
  EXPECT_EQ(r["repeated"], 0) << "requests whose caller was told twice";
  EXPECT_EQ(r["silent"], 0) << "requests never answered nor timed out";
  EXPECT_EQ(r["errors"], 0) << "failures other than a timeout";
  EXPECT_EQ(r["answered"] + r["timeouts"], r["requests"]);
  EXPECT_EQ(r["replies"], r["answered"]) << "each answer delivered once";
}

TEST(NetworkFaults, LossDelayDuplicationAndReorderingForAWholeRunEveryRequestAnsweredOnce) {
  FaultRun bed({kClean, kClean, kLossy});
  if (!bed.why_not().empty()) GTEST_SKIP() << bed.why_not();
  RunPlan plan;
  plan.rate_hz = 200.0;
  plan.duration_s = 10.0;
  plan.timeout = seconds(10);
  auto r = bed.run({1}, plan, {}, "lossy link (10 % loss, 20 +- 10 ms, 1 % duplication and reordering)");
  expect_each_request_answered_once_or_timed_out(r);
  EXPECT_EQ(r["timeouts"], 0) << "reliable delivery repairs a lossy link well within " << plan.timeout.count() << " ms";
  EXPECT_GE(r["p50_ms"], 40.0) << "a round trip crosses the 20 ms link twice: was the link's delay applied?";
}

TEST(NetworkFaults, AFiveSecondPartitionOfTheClientsHostThenHealedAnswersWithinFiveSeconds) {
  FaultRun bed({kClean, kClean, kLossy});
  if (!bed.why_not().empty()) GTEST_SKIP() << bed.why_not();
  RunPlan plan;
  plan.rate_hz = 200.0;
  plan.duration_s = 12.0;
  plan.timeout = seconds(3);
  auto r = bed.run({1}, plan, {kClientHost, seconds(5)}, "client's host partitioned for 5 s on the lossy link");
  expect_each_request_answered_once_or_timed_out(r);
  EXPECT_GT(r["timeouts"], 0) << "a 5 s partition fails the calls that wait 3 s for it: was the link cut?";
  EXPECT_GE(r["recovery_s"], 0.0) << "no answer after the heal";
  EXPECT_LT(r["recovery_s"], 5.0) << "the service answers within 5 s of the heal";
}

TEST(NetworkFaults, OneInstancesHostPartitionedWhileTheOtherServesEveryRequestAnsweredOnce) {
  FaultRun bed({kClean, kClean, kClean});
  if (!bed.why_not().empty()) GTEST_SKIP() << bed.why_not();
  RunPlan plan;
  plan.rate_hz = 200.0;
  plan.duration_s = 13.0;
  plan.timeout = seconds(10);
  auto r = bed.run({1, 2}, plan, {1, seconds(5)}, "host 1 (one of two instances) partitioned for 5 s");
  expect_each_request_answered_once_or_timed_out(r);
  EXPECT_EQ(r["timeouts"], 0) << "the instance on host 2 answers what host 1's could not";
  EXPECT_GT(r["resent"], 0) << "requests to the cut-off instance were sent again to the other";
  EXPECT_GE(r["rejoin_s"], 0.0) << "the healed instance was not found again";
  EXPECT_LT(r["rejoin_s"], 5.0) << "the healed instance is found again within 5 s";
  EXPECT_GT(r["least_served_after_heal"], 0) << "both instances serve again after the heal";
}

// A cut shorter than the leases (1 s; the instance's status liveliness is 2 s, the participants'
// 3 s): nothing is rediscovered, the requests written meanwhile reach the service when the link
// heals and are answered, but their callers gave up after 0.4 s. Those late replies must be
// dropped by the client, never handed to a caller a second time.
TEST(NetworkFaults, LateRepliesAfterAShortCutAreDroppedNeverHandedToACallerTwice) {
  FaultRun bed({kClean, kClean, kClean});
  if (!bed.why_not().empty()) GTEST_SKIP() << bed.why_not();
  RunPlan plan;
  plan.rate_hz = 200.0;
  plan.duration_s = 7.0;
  plan.timeout = milliseconds(400);
  auto r = bed.run({1}, plan, {kClientHost, seconds(1)}, "client's host cut for 1 s, 0.4 s timeout");
  expect_each_request_answered_once_or_timed_out(r);
  EXPECT_GT(r["timeouts"], 0) << "calls waiting 0.4 s through a 1 s cut time out: was the link cut?";
  EXPECT_GT(r["dropped_duplicates"], 0) << "the timed-out requests were answered after the heal, and dropped";
}

}  // namespace
}  // namespace gc::test
