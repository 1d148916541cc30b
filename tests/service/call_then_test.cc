// Client::call_then: the reply's callback gets what call() returns or throws, once, and may send
// the next request from inside the callback (a chain, as bench/service_bench.cc's listener mode).
#include <future>

#include <gtest/gtest.h>

#include "clients/remote/client.h"
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
