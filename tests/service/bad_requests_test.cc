// Bad requests of every kind get an error reply naming the field, with the type and message the
// core raises in process; the service keeps serving the next request.
#include <cmath>
#include <functional>
#include <limits>

#include <gtest/gtest.h>

#include "client/client.h"
#include "codec/coupling_catalog.h"
#include "protocol/reply_status.h"
#include "tests/service/service_process.h"

namespace gc {
namespace {

using protocol::Calculation;
using protocol::CatalogueName;

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// The what() of the InvalidInput `in_process` throws.
std::string in_process_message(const std::function<void()>& in_process) {
  try {
    in_process();
  } catch (const InvalidInput& e) {
    return e.what();
  }
  return "(no error in process)";
}

class BadRequests : public testing::Test {
 protected:
  BadRequests()
      : catalogue_(codec::load_coupling_catalog(codec::default_catalog_dir())),
        coupling_(catalogue_.at("nrel_upwind")) {}

  /// Sends an induced-moments request at `point` with `options` and expects the core's
  /// InvalidInput naming `field`, with the in-process message.
  void expect_invalid(const OperatingPoint& point, const ContactOptions& options,
                      const std::string& field) {
    SCOPED_TRACE(field);
    try {
      client_.call<Calculation::kInducedMoments>({CatalogueName{"nrel_upwind"}, point, options});
      ADD_FAILURE() << "no error reply";
    } catch (const InvalidInput& e) {
      EXPECT_EQ(e.field(), field);
      EXPECT_EQ(std::string(e.what()),
                in_process_message([&] { induced_moments(coupling_, point, options); }));
    }
  }

  void expect_invalid_coupling(CouplingDefinition definition, const std::string& field) {
    SCOPED_TRACE(field);
    try {
      client_.call<Calculation::kJamAngle>({definition});
      ADD_FAILURE() << "no error reply";
    } catch (const InvalidInput& e) {
      EXPECT_EQ(e.field(), field);
      EXPECT_EQ(std::string(e.what()),
                in_process_message([&] { CouplingGeometry geometry(definition); }));
    }
  }

  void expect_invalid_friction(const FrictionMeasurement& measurement, const std::string& field) {
    SCOPED_TRACE(field);
    try {
      client_.call<Calculation::kFrictionEstimate>({CatalogueName{"nrel_upwind"}, measurement});
      ADD_FAILURE() << "no error reply";
    } catch (const InvalidInput& e) {
      EXPECT_EQ(e.field(), field);
      EXPECT_EQ(std::string(e.what()),
                in_process_message([&] { estimate_friction(coupling_, measurement); }));
    }
  }

  test::ServiceProcess service_;
  client::Client client_{{test::test_domain(), std::chrono::seconds(20)}};
  std::map<std::string, CouplingGeometry> catalogue_;
  const CouplingGeometry& coupling_;
  OperatingPoint good_{1.0e6, 0.004, 0.0, 0.1};
};

TEST_F(BadRequests, EveryKindGetsAnErrorNamingTheFieldThenTheServiceAnswersTheNext) {
  // Unknown coupling.
  try {
    client_.call<Calculation::kJamAngle>({CatalogueName{"no_such_coupling"}});
    ADD_FAILURE() << "no error reply";
  } catch (const protocol::ServiceError& e) {
    EXPECT_EQ(e.status(), gearcoupling_STATUS_UNKNOWN_COUPLING);
    EXPECT_EQ(e.field(), "coupling.catalogue_name");
    EXPECT_NE(std::string(e.what()).find("nrel_upwind"), std::string::npos) << e.what();
  }
  // NaN and out-of-range operating points.
  OperatingPoint p = good_;
  p.torque_nm = kNaN;
  expect_invalid(p, {}, "operating_point.torque_nm");
  p = good_;
  p.torque_nm = -5.0;
  expect_invalid(p, {}, "operating_point.torque_nm");
  p = good_;
  p.misalignment_rad = 1.5 * coupling_.jam_angle().angle_rad;  // beyond the jam angle
  expect_invalid(p, {}, "operating_point.misalignment_rad");
  p = good_;
  p.direction_rad = std::numeric_limits<double>::infinity();
  expect_invalid(p, {}, "operating_point.direction_rad");
  p = good_;
  p.friction_coefficient = 1.5;
  expect_invalid(p, {}, "operating_point.friction_coefficient");
  // Options.
  ContactOptions options;
  options.slices = 7;
  expect_invalid(good_, options, "options.slices");
  options = {};
  options.load_sharing.tolerance = 0.0;
  expect_invalid(good_, options, "options.load_sharing.tolerance");
  options.load_sharing.tolerance = 1e308;  // issue 9: was blamed on the torque
  expect_invalid(good_, options, "options.load_sharing.tolerance");
  options = {};
  options.load_sharing.max_iterations = 2147483647;  // issue 9: held a worker indefinitely
  options.load_sharing.tolerance = 1e-15;
  expect_invalid(good_, options, "options.load_sharing.max_iterations");
  // Malformed inline geometry.
  CouplingDefinition definition = coupling_.definition();
  definition.backlash_m = 0.0;
  expect_invalid_coupling(definition, "coupling.backlash_m");
  definition = coupling_.definition();
  definition.teeth = 3;
  expect_invalid_coupling(definition, "coupling.teeth");
  definition = coupling_.definition();
  definition.pitch_diameter_m = kNaN;
  expect_invalid_coupling(definition, "coupling.pitch_diameter_m");
  // A bad measurement.
  try {
    client_.call<Calculation::kFrictionEstimate>(
        {CatalogueName{"nrel_upwind"}, FrictionMeasurement{1.0e6, 0.004, 0.0, kNaN, 0.0}});
    ADD_FAILURE() << "no error reply";
  } catch (const InvalidInput& e) {
    EXPECT_EQ(e.field(), "measurement.sensor_moment_y_nm");
  }
  // Issue 9: estimates of -1.51 and 2.28e301 came back as results.
  expect_invalid_friction({1.0e6, 1.0, 0.0, 1.0e5, 1.0e5}, "measurement.misalignment_rad");
  expect_invalid_friction({1.0e6, 0.004, 0.0, 1.0e5, 1.0e308}, "measurement.sensor_moment_z_nm");

  // The service still answers, correctly.
  const InducedMoments moments =
      client_.call<Calculation::kInducedMoments>({CatalogueName{"nrel_upwind"}, good_, {}});
  EXPECT_EQ(moments.magnitude_nm, induced_moments(coupling_, good_).magnitude_nm);
  EXPECT_TRUE(service_.running());
  EXPECT_EQ(client_.counters().timeouts, 0u);
}

}  // namespace
}  // namespace gc
