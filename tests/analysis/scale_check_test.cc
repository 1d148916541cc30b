// Unit slips in a recording's header (N·m under _knm, radians under _deg) are flagged by scale
// against the model, and a model merely a few times off is not.
#include <string>

#include <gtest/gtest.h>

#include "core/model_error.h"

#include "analysis/scale_check.h"

namespace gc::analysis {
namespace {

TEST(UnitSlipFactor, FindsPowersOfTenAndDegreesPerRadianEitherWay) {
  EXPECT_EQ(unit_slip_factor(1000.0), 1000.0);
  EXPECT_EQ(unit_slip_factor(1.0 / 1000.0), 1000.0);
  EXPECT_EQ(unit_slip_factor(9.0), 10.0);        // 10 within a factor of 1.5
  EXPECT_EQ(unit_slip_factor(130.0), 100.0);
  EXPECT_EQ(unit_slip_factor(57.3), 57.29577951308232);
  EXPECT_EQ(unit_slip_factor(1.0 / 60.0), 57.29577951308232);
}

TEST(UnitSlipFactor, LeavesAModelAFewTimesOffAlone) {
  EXPECT_EQ(unit_slip_factor(1.0), std::nullopt);
  EXPECT_EQ(unit_slip_factor(3.0), std::nullopt);
  EXPECT_EQ(unit_slip_factor(1.0 / 4.0), std::nullopt);
  EXPECT_EQ(unit_slip_factor(25.0), std::nullopt);   // between 15 and 38
  EXPECT_EQ(unit_slip_factor(0.0), std::nullopt);
}

// The measured M_sy' is N·m read as kN·m: 1000 times the model's, with noise on top.
TEST(MomentScale, WarnsForTheChannelAThousandTimesTheModel) {
  MomentScale scale;
  for (int i = 1; i <= 100; ++i) {
    const double model_y = 2e4 * i / 100.0, model_z = 1e4 * i / 100.0;
    scale.add({model_y * 1000.0 + 5e5, model_z + 300.0}, {model_y, model_z});
  }
  const std::vector<std::string> warnings = scale.warnings("paper");
  ASSERT_EQ(warnings.size(), 1u);
  EXPECT_NE(warnings[0].find("M_sy'"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[0].find("too large by about 1000"), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[0].find("msy column"), std::string::npos) << warnings[0];
  // Both RMS values in engineering notation: the measured in MN·m, the model's in kN·m.
  EXPECT_NE(warnings[0].find(" MN·m is "), std::string::npos) << warnings[0];
  EXPECT_NE(warnings[0].find("the model paper's 11.6 kN·m"), std::string::npos) << warnings[0];
  EXPECT_EQ(warnings[0].find("e+"), std::string::npos) << warnings[0];
}

TEST(MomentScale, QuietForAModelWithinNoise) {
  MomentScale scale;
  for (int i = 1; i <= 100; ++i) scale.add({1e4 * i + 2e3, 5e3 - 2e3}, {1e4 * i, 5e3});
  EXPECT_TRUE(scale.warnings("paper").empty());
  EXPECT_TRUE(MomentScale().warnings("none").empty());
}

// A channel the model holds near zero says nothing of units: its noise over a tiny RMS can
// land on any ratio.
TEST(MomentScale, DoesNotJudgeAChannelTheModelHoldsNearZero) {
  MomentScale scale;
  for (int i = 1; i <= 100; ++i) scale.add({1e4 * i, 2e3}, {1e4 * i, 200.0});
  EXPECT_TRUE(scale.warnings("paper").empty());
}

// 1000 is a kilo prefix slipped, refused by validate and diagnose; 10, 100 and 57.3 a model can
// be that wrong: warnings only.
TEST(MomentScale, RefusesOnlyAThousandfoldSlipEitherWay) {
  for (const double factor : {1000.0, 1.0 / 1000.0}) {
    MomentScale scale;
    for (int i = 1; i <= 100; ++i) scale.add({factor * 1e4 * i, 5e3}, {1e4 * i, 5e3});
    const auto refusal = scale.refusal("paper");
    ASSERT_TRUE(refusal) << factor;
    EXPECT_NE(refusal->find("M_sy'"), std::string::npos) << *refusal;
    EXPECT_NE(refusal->find("by about 1000"), std::string::npos) << *refusal;
    EXPECT_THROW(refuse_unit_slip("rec.csv", refusal), InvalidInput);
  }
  for (const double factor : {10.0, 100.0, 57.29577951308232}) {
    MomentScale scale;
    for (int i = 1; i <= 100; ++i) scale.add({factor * 1e4 * i, 5e3}, {1e4 * i, 5e3});
    EXPECT_EQ(scale.warnings("paper").size(), 1u) << factor;
    EXPECT_FALSE(scale.refusal("paper")) << factor;
  }
  EXPECT_NO_THROW(refuse_unit_slip("rec.csv", std::nullopt));
}

// Jam angle 0.0131 rad (the paper's upwind coupling); the bundled recordings reach 30-60 % of it.
TEST(MisalignmentScale, FlagsRadiansUnderDegreesAndDegreesUnderRadians) {
  const double jam = 0.0131;
  const double radians_read_as_degrees = 0.6 * jam / 57.29577951308232;
  const auto small = misalignment_scale_warning(radians_read_as_degrees, jam);
  ASSERT_TRUE(small);
  EXPECT_NE(small->find("radians under a _deg header"), std::string::npos) << *small;
  const auto large = misalignment_scale_warning(0.6 * jam * 57.29577951308232, jam);
  ASSERT_TRUE(large);
  EXPECT_NE(large->find("degrees under a _rad header"), std::string::npos) << *large;
  EXPECT_FALSE(misalignment_scale_warning(0.3 * jam, jam));
  EXPECT_FALSE(misalignment_scale_warning(1.2 * jam, jam));
  EXPECT_FALSE(misalignment_scale_warning(0.0, jam));   // an aligned test: nothing to judge
}

// Issue 39: one wording for every place that checks units, each with its own fix.
TEST(UnitSlipError, NamesTheUnitErrorAndTheFixOfEachPlace) {
  const std::string finding = "M_sy' measured RMS 155 N·m is 0.001 times the model paper's 155 kN·m";
  const std::string cli = unit_slip_error("rec.csv", finding, UnitFix::cli);
  EXPECT_EQ(cli.rfind("rec.csv: unit error: " + finding + "; a fit to moments 1000 times off says nothing: ", 0), 0u) << cli;
  EXPECT_NE(cli.find("--columns msy_knm=HEADER"), std::string::npos) << cli;
  EXPECT_NE(cli.find("--force-scale"), std::string::npos) << cli;
  const std::string python = unit_slip_error("<DataFrame>", finding, UnitFix::python);
  EXPECT_NE(python.find("columns={'msy_knm': 'HEADER'}"), std::string::npos) << python;
  EXPECT_NE(python.find("force_scale=True"), std::string::npos) << python;
  const std::string stream = unit_slip_error("test cell dyno", finding, UnitFix::stream);
  EXPECT_NE(stream.find("the publisher must send N·m"), std::string::npos) << stream;
  try {
    refuse_unit_slip("rec.csv", finding);
    ADD_FAILURE() << "not refused";
  } catch (const InvalidInput& error) {
    EXPECT_EQ(error.field(), "recording");
    EXPECT_EQ(std::string(error.what()), "recording: " + cli);   // InvalidInput names its field
  }
}

// Issue 39: kN·m under torque_nm gave only "light torque near the jam angle is outside eq 22's
// range". T_ref 1.5 MN·m; a test runs at 0.1 to 3 T_ref.
TEST(TorqueScale, FlagsKilonewtonMetresUnderAnNmHeader) {
  const auto slipped = torque_scale_warning(2.2e3, 1.5e6);   // 2.2 MN·m read as 2.2 kN·m
  ASSERT_TRUE(slipped);
  EXPECT_NE(slipped->find("torque reaches only 2.20 kN·m"), std::string::npos) << *slipped;
  EXPECT_NE(slipped->find("kN·m under a _nm header? (1000 times too small"), std::string::npos) << *slipped;
  EXPECT_FALSE(torque_scale_warning(2.2e6, 1.5e6));   // as it should be
  EXPECT_FALSE(torque_scale_warning(2e4, 1.5e6));     // 1.3 % of T_ref: a light test, not a slip
  EXPECT_FALSE(torque_scale_warning(10.0, 1.5e6));    // x 1000 still under 0.1 T_ref
  EXPECT_FALSE(torque_scale_warning(0.0, 1.5e6));
}

}  // namespace
}  // namespace gc::analysis
