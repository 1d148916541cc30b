// Mains pickup, direct or aliased by a slow DAQ, is taken out of the time terms; an aliased line
// where a shaft or mesh order also lies is left to the physics (diagnosis/mains_pickup.h).
#include <gtest/gtest.h>

#include <cmath>
#include <random>
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

/// A residual with no line: white noise of 100 N·m.
Eigen::MatrixX2d quiet(std::size_t n) {
  std::mt19937_64 random(11);
  std::normal_distribution<double> normal(0.0, 100.0);
  Eigen::MatrixX2d r(static_cast<Eigen::Index>(n), 2);
  for (Eigen::Index i = 0; i < r.rows(); ++i) r.row(i) << normal(random), normal(random);
  return r;
}

// 50 Hz sampled at 11 Hz shows at 5 Hz (a zoo draw's grid 0.07 Hz low: 5.016 Hz); the shaft at 6 rpm
// and a 56-tooth mesh (5.6 Hz) are elsewhere, so it is mains.
TEST(MainsPickup, AnAliasedLineAwayFromEveryOrderIsMains) {
  const std::vector<RecordedSample> rows = rows_at(11.0, 1052, 6.0);
  std::vector<std::string> terms{"time_cycle_0.199374s_cos_on_y", "time_cycle_0.199374s_sin_on_y"};
  const std::string text = take_out_mains_cycles(terms, rows, all(rows.size()), quiet(rows.size()), 56);
  EXPECT_TRUE(terms.empty());
  EXPECT_NE(text.find("50 Hz aliased"), std::string::npos) << text;
}

// The grid deviates by up to 0.5 % of its frequency, and its alias by as many hertz: 60 Hz
// sampled at 58.3 Hz shows at 1.7 Hz, and a grid 0.065 Hz low at 1.635 Hz (noise zoo seed 20261315,
// draw 251: claimed as a time cycle of 0.6118 s, 3,938 rows). 0.4 Hz off is no longer the grid's.
TEST(MainsPickup, AnAliasedLineMovesWithTheGridsDeviationInHertz) {
  EXPECT_EQ(mains_frequency(1.635, 58.3, 1.0 / 67.5), 60.0);
  EXPECT_EQ(mains_frequency(1.765, 58.3, 1.0 / 67.5), 60.0);
  EXPECT_FALSE(mains_frequency(2.1, 58.3, 1.0 / 67.5).has_value());
  const std::vector<RecordedSample> rows = rows_at(58.3, 3938, 0.5);
  std::vector<std::string> terms{"time_cycle_0.611766s_sin_on_y", "time_cycle_0.611766s_sin_on_z"};
  EXPECT_NE(take_out_mains_cycles(terms, rows, all(rows.size()), quiet(rows.size()), 56).find("60 Hz aliased"),
            std::string::npos);
  EXPECT_TRUE(terms.empty());
}

// 60 Hz sampled at 50 Hz shows at 10 Hz, where a 56-tooth mesh at 10.7 rpm (9.99 Hz) also is: kept.
TEST(MainsPickup, AnAliasedLineOnAMeshOrderIsLeftToThePhysics) {
  const std::vector<RecordedSample> rows = rows_at(50.0, 5000, 10.7);
  std::vector<std::string> terms{"time_cycle_0.1s_cos_on_z"};
  EXPECT_EQ(take_out_mains_cycles(terms, rows, all(rows.size()), quiet(rows.size()), 56), "");
  EXPECT_EQ(terms.size(), 1u);
  // Without a recorded speed nothing says it is an order: mains.
  std::vector<RecordedSample> no_speed = rows;
  for (RecordedSample& r : no_speed) r.input.speed_rpm.reset();
  EXPECT_NE(take_out_mains_cycles(terms, no_speed, all(no_speed.size()), quiet(no_speed.size()), 56), "");
  EXPECT_TRUE(terms.empty());
}

// 60 Hz sampled at 38 Hz shows at 16.0 Hz. The shaft wanders 6.7-14.2 rpm, so a 100-tooth mesh passes
// 16 Hz at some speeds (zoo seed 20261225 draw 362). A line there on every row, at speeds where no
// order is near, is mains; a line only on the rows whose speed puts the mesh there is left to the
// physics.
TEST(MainsPickup, AnAliasedLineAlsoWhereNoOrderCanBeIsMains) {
  std::vector<RecordedSample> rows = rows_at(38.0, 1553, 10.0);
  for (std::size_t i = 0; i < rows.size(); ++i) {
    rows[i].input.speed_rpm = 10.45 + 3.75 * std::sin(2.0 * M_PI * static_cast<double>(i) / 1553.0 * 1.5);
  }
  const double f = 16.0;
  const auto mesh_near = [&](const RecordedSample& r) {
    for (int order = 98; order <= 102; ++order) {
      double seen = std::fmod(order * *r.input.speed_rpm / 60.0, 38.0);
      if (seen > 19.0) seen = 38.0 - seen;
      if (std::abs(seen - f) < 0.2) return true;
    }
    return false;
  };
  Eigen::MatrixX2d everywhere = quiet(rows.size()), near_only = quiet(rows.size());
  std::size_t near = 0;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const double line = 200.0 * std::cos(2.0 * M_PI * f * rows[i].input.time_s);
    everywhere(static_cast<Eigen::Index>(i), 0) += line;
    if (mesh_near(rows[i])) {
      near_only(static_cast<Eigen::Index>(i), 0) += line;
      ++near;
    }
  }
  ASSERT_GT(near, 50u);
  ASSERT_LT(near, rows.size() / 2);
  std::vector<std::string> terms{"time_cycle_0.0625s_cos_on_y", "time_cycle_0.0625s_sin_on_y"};
  EXPECT_NE(take_out_mains_cycles(terms, rows, all(rows.size()), everywhere, 100).find("60 Hz aliased"), std::string::npos);
  EXPECT_TRUE(terms.empty());
  terms = {"time_cycle_0.0625s_cos_on_y", "time_cycle_0.0625s_sin_on_y"};
  EXPECT_EQ(take_out_mains_cycles(terms, rows, all(rows.size()), near_only, 100), "");
  EXPECT_EQ(terms.size(), 2u);
}

// A lightly damped ringing at the mains frequency, driven by a torque that never stops moving, is a
// narrow line: 50 Hz pickup sampled at 852 Hz for 1.85 s was claimed as the rig ringing at 49.7 and
// 50.7 Hz with a damping of 0.01 (zoo seed 20261227 draw 71). A well damped mode there, and a
// lightly damped one elsewhere, are the rig's.
TEST(MainsPickup, ALightlyDampedRingingAtTheMainsFrequencyIsMains) {
  const std::vector<RecordedSample> rows = rows_at(852.0, 1580, 10.0);
  std::vector<std::string> terms{"ringing_50.7Hz_zeta0.01_on_y", "ringing_50.7Hz_zeta0.01_on_z"};
  EXPECT_NE(take_out_mains_cycles(terms, rows, all(rows.size()), quiet(rows.size()), 100), "");
  EXPECT_TRUE(terms.empty());
  terms = {"ringing_50.7Hz_zeta0.2_on_y", "ringing_31Hz_zeta0.01_on_y"};
  EXPECT_EQ(take_out_mains_cycles(terms, rows, all(rows.size()), quiet(rows.size()), 100), "");
  EXPECT_EQ(terms.size(), 2u);
}

// A direct line at 50 Hz, sampled at 1 kHz, is mains whatever the shaft does.
TEST(MainsPickup, ADirectLineIsMains) {
  const std::vector<RecordedSample> rows = rows_at(1000.0, 20000, 10.7);
  std::vector<std::string> terms{"time_cycle_0.02s_cos_on_y"};
  EXPECT_NE(take_out_mains_cycles(terms, rows, all(rows.size()), quiet(rows.size()), 56), "");
  EXPECT_TRUE(terms.empty());
}

}  // namespace
}  // namespace gc
