// The request conversions of protocol/wire_inputs.h, without DDS: every ContactOptions member
// the core reads reaches the service unchanged.
#include "protocol/wire_inputs.h"

#include <gtest/gtest.h>

namespace gc {
namespace {

TEST(WireInputs, ContactOptionsRoundTripEveryMember) {
  for (bool continuous : {false, true}) {
    ContactOptions options;
    options.load_sharing.tolerance = 1e-7;
    options.load_sharing.max_iterations = 42;
    options.slices = 16;
    options.spacing_error_m = 2e-5;
    options.min_load_fraction = 0.8;
    options.continuous_quarter_sums = continuous;  // issue 8, docs/model.md
    gearcoupling_ContactOptions wire{};
    protocol::to_wire(options, wire);
    EXPECT_EQ(wire.continuous_quarter_sums, continuous);
    const ContactOptions back = protocol::from_wire(wire);
    EXPECT_EQ(back.continuous_quarter_sums, continuous);
    EXPECT_EQ(back.load_sharing.tolerance, 1e-7);
    EXPECT_EQ(back.load_sharing.max_iterations, 42);
    EXPECT_EQ(back.slices, 16);
    EXPECT_EQ(back.spacing_error_m, 2e-5);
    EXPECT_EQ(back.min_load_fraction, 0.8);
  }
}

}  // namespace
}  // namespace gc
