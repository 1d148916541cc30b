// Each calculation through the service equals the in-process result bit for bit, for catalogue
// couplings and inline ones (expected values: the core called directly in this process on the
// same coupling files the service loads).
#include <gtest/gtest.h>

#include "client/client.h"
#include "codec/coupling_catalog.h"
#include "tests/service/identical.h"
#include "tests/service/service_process.h"

namespace gc {
namespace {

using protocol::Calculation;
using protocol::CatalogueName;

std::vector<OperatingPoint> load_cases(const CouplingGeometry& coupling) {
  std::vector<OperatingPoint> cases;
  const double jam = coupling.jam_angle().angle_rad;
  for (double torque : {2.0e5, 1.5e6, 3.4e6}) {
    for (double fraction : {0.0, 0.3, 0.9}) {
      cases.push_back({torque, fraction * jam, 0.4, 0.12});
    }
  }
  return cases;
}

TEST(Service, EveryCalculationEqualsInProcessBitForBit) {
  test::ServiceProcess service;
  client::Client client({.domain = test::test_domain(), .timeout = std::chrono::seconds(20)});
  const auto catalogue = codec::load_coupling_catalog(codec::default_catalog_dir());
  ASSERT_FALSE(catalogue.empty());
  ContactOptions options;
  options.slices = 16;
  ContactOptions continuous = options;  // issue 8: the option must reach the service's core
  continuous.continuous_quarter_sums = true;
  for (const auto& [name, geometry] : catalogue) {
    for (const protocol::CouplingRef& ref :
         {protocol::CouplingRef{CatalogueName{name}}, protocol::CouplingRef{geometry.definition()}}) {
      SCOPED_TRACE(name + (ref.index() == 0 ? " by name" : " inline"));
      const protocol::JamAngleResult jam = client.call<Calculation::kJamAngle>({ref});
      test::expect_identical(jam.jam, geometry.jam_angle());
      EXPECT_EQ(test::bits(jam.crown_radius_m), test::bits(geometry.crown_radius_m()));
      EXPECT_EQ(jam.crown_radius_derived, geometry.crown_radius_derived());
      test::expect_identical(client.call<Calculation::kRestoringTorque>({ref}),
                             restoring_torque(geometry));
      for (const OperatingPoint& point : load_cases(geometry)) {
        test::expect_identical(client.call<Calculation::kToothContact>({ref, point, options}),
                               tooth_contact(geometry, point, options));
        test::expect_identical(client.call<Calculation::kInducedMoments>({ref, point, options}),
                               induced_moments(geometry, point, options));
        test::expect_identical(client.call<Calculation::kInducedMoments>({ref, point, continuous}),
                               induced_moments(geometry, point, continuous));
        const InducedMoments moments = induced_moments(geometry, point, options);
        const FrictionMeasurement measurement{point.torque_nm, point.misalignment_rad,
                                              point.direction_rad, moments.sensor_moment_y_nm,
                                              moments.sensor_moment_z_nm};
        if (point.misalignment_rad > 0.0) {
          test::expect_identical(
              client.call<Calculation::kFrictionEstimate>({ref, measurement}),
              estimate_friction(geometry, measurement));
        }
      }
    }
  }
  const client::ClientCounters counters = client.counters();
  EXPECT_EQ(counters.replies, counters.sent);
  EXPECT_GE(counters.replies, 100u);  // 2 couplings x 2 references x (2 + 9 x 4 - 3)
  EXPECT_EQ(counters.duplicates, 0u);
  EXPECT_EQ(counters.foreign, 0u);
}

}  // namespace
}  // namespace gc
