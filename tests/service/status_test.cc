// The status topic tells clients and dashboards what an instance serves and how it is doing.
#include <gtest/gtest.h>

#include "client/client.h"
#include "codec/coupling_catalog.h"
#include "core/model_error.h"
#include "protocol/matching.h"
#include "tests/service/identical.h"
#include "tests/service/service_process.h"

namespace gc {
namespace {

using protocol::Calculation;
using protocol::CatalogueName;

// A request the service refuses for its input (here an unknown coupling) is the client's, not a
// failure of the service: counted as refused, not failed (issue 25).
TEST(Service, StatusReportsCatalogueAndRequestsServedAndRefused) {
  test::ServiceProcess service({"--status-interval-s", "0.1", "--jobs", "2"});
  client::Client client({test::test_domain(), std::chrono::seconds(10)});
  for (int r = 0; r < 10; ++r) client.call<Calculation::kJamAngle>({CatalogueName{"nrel_upwind"}});
  for (int r = 0; r < 3; ++r) {
    EXPECT_THROW(client.call<Calculation::kJamAngle>({CatalogueName{"unknown"}}), ModelError);
  }
  client::CalculationStatus jam;
  const auto jam_counts = [&] {
    for (const client::InstanceInfo& instance : client.instances()) {
      for (const client::CalculationStatus& c : instance.calculations) {
        if (c.calculation == "jam_angle") jam = c;
      }
    }
  };
  ASSERT_TRUE(protocol::wait_until(
      [&] {
        jam_counts();
        return jam.served == 10 && jam.refused == 3;
      },
      std::chrono::steady_clock::now() + std::chrono::seconds(5)))
      << "served " << jam.served << " refused " << jam.refused << " failed " << jam.failed;
  EXPECT_EQ(jam.failed, 0u);
  EXPECT_GT(jam.service_time_sum_s, 0.0);
  EXPECT_LT(jam.service_time_sum_s, 13.0);
  const std::vector<client::InstanceInfo> instances = client.instances();
  ASSERT_EQ(instances.size(), 1u);
  const client::InstanceInfo& instance = instances.front();
  EXPECT_EQ(instance.pid, service.pid());
  EXPECT_TRUE(instance.accepting);
  EXPECT_EQ(instance.threads, 2u);
  EXPECT_GT(instance.uptime_s, 0.0);
  EXPECT_EQ(instance.catalogue, (std::vector<std::string>{"nrel_downwind", "nrel_upwind"}));
  ASSERT_EQ(instance.calculations.size(), protocol::kCalculationCount);
  for (const client::CalculationStatus& c : instance.calculations) {
    EXPECT_EQ(c.called(), c.calculation == "jam_angle") << c.calculation;
    if (c.calculation != "jam_angle") continue;
    EXPECT_GT(c.p50_service_time_s, 0.0);
    EXPECT_GE(c.p99_service_time_s, c.p50_service_time_s);
    EXPECT_LT(c.p99_service_time_s, 1.0);
  }
}

// A client can fetch a catalogue coupling's whole definition from the status, and a request that
// carries it inline gets the same answer, bit for bit, as one by name.
TEST(Service, StatusCarriesEachCatalogueCouplingsDefinition) {
  test::ServiceProcess service({"--status-interval-s", "0.1"});
  client::Client client({test::test_domain(), std::chrono::seconds(10)});
  ASSERT_TRUE(client.wait_for_service(Calculation::kJamAngle, std::chrono::seconds(10)));
  ASSERT_TRUE(protocol::wait_until([&] { return client.catalogue_definition("nrel_downwind").has_value(); },
                                   std::chrono::steady_clock::now() + std::chrono::seconds(5)));
  const CouplingDefinition remote = *client.catalogue_definition("nrel_downwind");
  const auto catalogue = codec::load_coupling_catalog(codec::default_catalog_dir());
  const CouplingDefinition& local = catalogue.at("nrel_downwind").definition();
  EXPECT_EQ(remote.name, "nrel_downwind");
  EXPECT_EQ(remote.teeth, local.teeth);
  EXPECT_EQ(test::bits(remote.facewidth_m), test::bits(local.facewidth_m));
  EXPECT_EQ(remote.crown_radius_m.has_value(), local.crown_radius_m.has_value());
  EXPECT_FALSE(client.catalogue_definition("no_such_coupling").has_value());
  const auto by_name = client.call<Calculation::kJamAngle>({CatalogueName{"nrel_downwind"}});
  const auto inline_definition = client.call<Calculation::kJamAngle>({remote});
  EXPECT_EQ(test::bits(by_name.jam.angle_rad), test::bits(inline_definition.jam.angle_rad));
  EXPECT_EQ(test::bits(by_name.crown_radius_m), test::bits(inline_definition.crown_radius_m));
  ASSERT_EQ(client.instances().size(), 1u);
  EXPECT_EQ(client.instances()[0].definitions.size(), client.instances()[0].catalogue.size());
}

}  // namespace
}  // namespace gc
