// Client::call_then: the reply's callback gets what call() returns or throws, once, and may send
// the next request from inside the callback (a chain, as bench/service_bench.cc's listener mode).
#include <atomic>
#include <future>
#include <iostream>

#include <gtest/gtest.h>

#include "client/client.h"
#include "core/model_error.h"
#include "tests/service/service_process.h"

namespace gc {
namespace {

using protocol::Calculation;
using protocol::CatalogueName;

const protocol::InducedMomentsRequest kRequest{CatalogueName{"nrel_upwind"},
                                               OperatingPoint{1.5e6, 0.007, 0.0, 0.1}, {}};

TEST(CallThen, TheCallbackGetsWhatCallReturns) {
  test::ServiceProcess service;
  client::Client client({test::test_domain(), std::chrono::seconds(20)});
  const InducedMoments expected = client.call<Calculation::kInducedMoments>(kRequest);
  std::promise<client::Outcome<InducedMoments>> got;
  client.call_then<Calculation::kInducedMoments>(
      kRequest, [&](client::Outcome<InducedMoments> outcome) { got.set_value(std::move(outcome)); });
  const client::Outcome<InducedMoments> outcome = got.get_future().get();
  ASSERT_FALSE(outcome.error);
  EXPECT_EQ(outcome.value().moment_y_nm, expected.moment_y_nm);
  EXPECT_EQ(outcome.value().moment_z_nm, expected.moment_z_nm);
}

TEST(CallThen, AnErrorReplyReachesTheCallbackAsTheCoreExceptionType) {
  test::ServiceProcess service;
  client::Client client({test::test_domain(), std::chrono::seconds(20)});
  protocol::InducedMomentsRequest bad = kRequest;
  bad.operating_point.torque_nm = -1.0;
  std::promise<client::Outcome<InducedMoments>> got;
  client.call_then<Calculation::kInducedMoments>(
      bad, [&](client::Outcome<InducedMoments> outcome) { got.set_value(std::move(outcome)); });
  const client::Outcome<InducedMoments> outcome = got.get_future().get();
  ASSERT_TRUE(outcome.error);
  EXPECT_FALSE(outcome.result);
  try {
    outcome.value();
    ADD_FAILURE() << "no exception";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.field(), "operating_point.torque_nm");
  }
}

TEST(CallThen, ACallbackMaySendTheNextRequest) {
  test::ServiceProcess service;
  client::Client client({test::test_domain(), std::chrono::seconds(20)});
  ASSERT_TRUE(client.wait_for_service(Calculation::kJamAngle, std::chrono::seconds(20)));
  constexpr int kChain = 200;
  int answered = 0;
  std::promise<void> done;
  client::Client::Callback<Calculation::kJamAngle> next = [&](client::Outcome<protocol::JamAngleResult> outcome) {
    if (outcome.error || ++answered == kChain) {
      done.set_value();
      return;
    }
    client.call_then<Calculation::kJamAngle>({CatalogueName{"nrel_upwind"}}, next);
  };
  client.call_then<Calculation::kJamAngle>({CatalogueName{"nrel_upwind"}}, next);
  ASSERT_EQ(done.get_future().wait_for(std::chrono::seconds(30)), std::future_status::ready);
  EXPECT_EQ(answered, kChain);
  EXPECT_EQ(client.counters().replies, static_cast<std::uint64_t>(kChain));
  EXPECT_EQ(client.counters().timeouts, 0u);
}

// A callback runs in Cyclone's receive thread, the thread that also takes the service's
// acknowledgements and replies. A burst sent from it fills the request writer's window (the
// writer history cache's high-water mark, 30 kB at first) and the client's 256 requests in
// flight: waiting there, for acknowledgements or answers its own thread has to read, would stall
// the client (for the writer's max blocking time, 10 s, before this was fixed). The callback
// defers those writes to the client's own thread instead.
TEST(CallThen, ABurstSentFromACallbackIsAnsweredWithoutWaitingForItself) {
  test::ServiceProcess service;
  client::Client client({test::test_domain(), std::chrono::seconds(5)});
  ASSERT_TRUE(client.wait_for_service(Calculation::kInducedMoments, std::chrono::seconds(20)));
  constexpr int kBurst = 3000;
  std::atomic<int> answered{0};
  std::atomic<int> failed{0};
  std::promise<void> done;
  auto count = [&](client::Outcome<InducedMoments> outcome) {
    if (outcome.error) failed += 1;
    if (answered.fetch_add(1) + 1 == kBurst) done.set_value();
  };
  client.call_then<Calculation::kInducedMoments>(kRequest, [&](client::Outcome<InducedMoments>) {
    for (int r = 0; r < kBurst; ++r) client.call_then<Calculation::kInducedMoments>(kRequest, count);
  });
  ASSERT_EQ(done.get_future().wait_for(std::chrono::seconds(30)), std::future_status::ready);
  EXPECT_EQ(failed, 0);
  const client::ClientCounters counters = client.counters();
  EXPECT_EQ(counters.timeouts, 0u);
  EXPECT_EQ(counters.replies, static_cast<std::uint64_t>(kBurst + 1));
  EXPECT_EQ(counters.sent, static_cast<std::uint64_t>(kBurst + 1));
  std::cout << "writes deferred from the callback: " << counters.deferred << "\n";
  EXPECT_GT(counters.deferred, 0u);  // the burst did fill the window: the path was taken
}

TEST(CallThen, WithNoServiceTheCallbackGetsTheTimeout) {
  client::Client client({test::test_domain(), std::chrono::milliseconds(300)});
  std::promise<client::Outcome<protocol::JamAngleResult>> got;
  client.call_then<Calculation::kJamAngle>(
      {CatalogueName{"nrel_upwind"}},
      [&](client::Outcome<protocol::JamAngleResult> outcome) { got.set_value(std::move(outcome)); });
  const client::Outcome<protocol::JamAngleResult> outcome = got.get_future().get();
  ASSERT_TRUE(outcome.error);
  EXPECT_THROW(outcome.value(), client::Timeout);
}

}  // namespace
}  // namespace gc
