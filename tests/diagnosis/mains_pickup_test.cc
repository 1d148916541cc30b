// Mains pickup, direct or aliased by a slow DAQ, is taken out of the time terms; an aliased line
// where a shaft or mesh order also lies is left to the physics (diagnosis/mains_pickup.h).
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "diagnosis/mains_pickup.h"

namespace gc {
namespace {

/// `count` rows at `rate_hz`, the shaft at `speed_rpm`.
std::vector<RecordedSample> rows_at(double rate_hz, int count, double speed_rpm) {
  std::vector<RecordedSample> out(static_cast<std::size_t>(count));
  for (int i = 0; i < count; ++i) {
    out[static_cast<std::size_t>(i)].input.time_s = 1147.0 + i / rate_hz;
    out[static_cast<std::size_t>(i)].input.speed_rpm = speed_rpm;
  }
  return out;
}

std::vector<std::size_t> all(std::size_t n) {
  std::vector<std::size_t> out(n);
  for (std::size_t i = 0; i < n; ++i) out[i] = i;
  return out;
}

// 50 Hz sampled at 11 Hz shows at 5 Hz (a zoo draw's grid 0.07 Hz low: 5.016 Hz); the shaft at 6 rpm
// and a 56-tooth mesh (5.6 Hz) are elsewhere, so it is mains.
TEST(MainsPickup, AnAliasedLineAwayFromEveryOrderIsMains) {
  const std::vector<RecordedSample> rows = rows_at(11.0, 1052, 6.0);
  std::vector<std::string> terms{"time_cycle_0.199374s_cos_on_y", "time_cycle_0.199374s_sin_on_y"};
  const std::string text = take_out_mains_cycles(terms, rows, all(rows.size()), 56);
  EXPECT_TRUE(terms.empty());
  EXPECT_NE(text.find("50 Hz aliased"), std::string::npos) << text;
}

// 60 Hz sampled at 50 Hz shows at 10 Hz, where a 56-tooth mesh at 10.7 rpm (9.99 Hz) also is: kept.
TEST(MainsPickup, AnAliasedLineOnAMeshOrderIsLeftToThePhysics) {
  const std::vector<RecordedSample> rows = rows_at(50.0, 5000, 10.7);
  std::vector<std::string> terms{"time_cycle_0.1s_cos_on_z"};
  EXPECT_EQ(take_out_mains_cycles(terms, rows, all(rows.size()), 56), "");
  EXPECT_EQ(terms.size(), 1u);
  // Without a recorded speed nothing says it is an order: mains.
  std::vector<RecordedSample> no_speed = rows;
  for (RecordedSample& r : no_speed) r.input.speed_rpm.reset();
  EXPECT_NE(take_out_mains_cycles(terms, no_speed, all(no_speed.size()), 56), "");
  EXPECT_TRUE(terms.empty());
}

// A direct line at 50 Hz, sampled at 1 kHz, is mains whatever the shaft does.
TEST(MainsPickup, ADirectLineIsMains) {
  const std::vector<RecordedSample> rows = rows_at(1000.0, 20000, 10.7);
  std::vector<std::string> terms{"time_cycle_0.02s_cos_on_y"};
  EXPECT_NE(take_out_mains_cycles(terms, rows, all(rows.size()), 56), "");
  EXPECT_TRUE(terms.empty());
}

}  // namespace
}  // namespace gc
