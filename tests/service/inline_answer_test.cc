// Which requests the service answers in its request listener (service/inline_answer.h), and
// that it does: lone cheap requests are counted there, costly ones go to the workers.
#include <signal.h>

#include <fstream>
#include <regex>
#include <sstream>

#include <gtest/gtest.h>

#include "client/client.h"
#include "codec/coupling_catalog.h"
#include "service/inline_answer.h"
#include "tests/service/scaled_coupling.h"
#include "tests/service/read_text.h"
#include "tests/service/service_process.h"

namespace gc {
namespace {

using protocol::Calculation;
using protocol::CatalogueName;

service::Catalogue nrel_catalogue() {
  return service::Catalogue(codec::load_coupling_catalog(codec::default_catalog_dir()));
}

CouplingDefinition with_teeth(int teeth) { return test::scaled_coupling(teeth); }

const OperatingPoint kPoint{1.5e6, 0.007, 0.0, 0.1};

TEST(InlineAnswer, DefaultRequestsOnTheBundledCouplingsAreCheap) {
  const service::Catalogue catalogue = nrel_catalogue();
  const protocol::CouplingRef upwind = CatalogueName{"nrel_upwind"};
  EXPECT_TRUE(service::cheap_to_answer(protocol::ToothContactRequest{upwind, kPoint, {}}, catalogue));
  EXPECT_TRUE(service::cheap_to_answer(protocol::InducedMomentsRequest{upwind, kPoint, {}}, catalogue));
  EXPECT_TRUE(service::cheap_to_answer(protocol::JamAngleRequest{upwind}, catalogue));
  EXPECT_TRUE(service::cheap_to_answer(protocol::RestoringTorqueRequest{upwind}, catalogue));
  // An unknown name is answered at once with an error.
  EXPECT_TRUE(service::cheap_to_answer(protocol::JamAngleRequest{CatalogueName{"nope"}}, catalogue));
  EXPECT_EQ(service::teeth_of(upwind, catalogue), 100);
  EXPECT_EQ(ContactOptions{}.slices * ContactOptions{}.load_sharing.max_iterations,
            service::kInlineContactWorkBound);
}

TEST(InlineAnswer, MoreSlicesIterationsOrTeethThanTheBoundsGoToTheWorkers) {
  const service::Catalogue catalogue = nrel_catalogue();
  ContactOptions slices;
  slices.slices = 1000;
  ContactOptions iterations;
  iterations.load_sharing.max_iterations = kMaxLoadSharingIterations;
  ContactOptions fewer_slices_more_iterations;  // the product is what bounds the work
  fewer_slices_more_iterations.slices = 10;
  fewer_slices_more_iterations.load_sharing.max_iterations = 200;
  const protocol::CouplingRef upwind = CatalogueName{"nrel_upwind"};
  EXPECT_FALSE(service::cheap_to_answer(protocol::ToothContactRequest{upwind, kPoint, slices}, catalogue));
  EXPECT_FALSE(service::cheap_to_answer(protocol::InducedMomentsRequest{upwind, kPoint, iterations}, catalogue));
  EXPECT_TRUE(service::cheap_to_answer(
      protocol::InducedMomentsRequest{upwind, kPoint, fewer_slices_more_iterations}, catalogue));
  EXPECT_TRUE(service::cheap_to_answer(protocol::JamAngleRequest{with_teeth(200)}, catalogue));
  EXPECT_FALSE(service::cheap_to_answer(protocol::JamAngleRequest{with_teeth(201)}, catalogue));
  EXPECT_FALSE(service::cheap_to_answer(protocol::ToothContactRequest{with_teeth(10000), kPoint, {}}, catalogue));
}

TEST(InlineAnswer, LoneCheapRequestsAreAnsweredInTheListenerAndCostlyOnesOnWorkers) {
  const std::string log = ::testing::TempDir() + "inline_answer_service.log";
  {
    test::ServiceProcess service({"--log-level", "info", "--stats-interval-s", "60"}, log);
    client::Client client({test::test_domain(), std::chrono::seconds(20)});
    const protocol::CouplingRef upwind = CatalogueName{"nrel_upwind"};
    for (int i = 0; i < 20; ++i) client.call<Calculation::kJamAngle>({upwind});
    ContactOptions slices;
    slices.slices = 1000;
    client.call<Calculation::kToothContact>({upwind, kPoint, slices});
    client.call<Calculation::kJamAngle>({with_teeth(300)});
    // Answered in the listener or not, the results are the same.
    const InducedMoments moments = client.call<Calculation::kInducedMoments>({upwind, kPoint, {}});
    const auto geometry = codec::load_coupling_catalog(codec::default_catalog_dir()).at("nrel_upwind");
    EXPECT_EQ(moments.moment_y_nm, induced_moments(geometry, kPoint, ContactOptions{}).moment_y_nm);
    service.signal(SIGTERM);
    ASSERT_EQ(service.wait_exit(20), 0);
  }
  // The last stats line (written at shutdown) counts the 20 jam angles and the moments: 21, never
  // the two costly ones. A request that arrives before the service has seen the client's reply
  // reader waits for it and then goes to a worker: the first may, on a loaded host.
  const std::string text = test::read_text(log);
  const std::regex count("answered_in_listener=([0-9]+)");
  int last = -1;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), count); it != std::sregex_iterator(); ++it) {
    last = std::stoi((*it)[1]);
  }
  EXPECT_GE(last, 19) << text;
  EXPECT_LE(last, 21) << text;
}

}  // namespace
}  // namespace gc
