// Every subcommand run as the user runs it: tables and --json against the in-process core,
// bad input against exit code 2 and a one-line message naming the flag, value and range.
#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <google/protobuf/util/json_util.h>
#include <gtest/gtest.h>

#include "codec/coupling_catalog.h"
#include "core/coupling_geometry.h"
#include "core/friction_estimate.h"
#include "core/induced_moments.h"
#include "core/restoring_torque.h"
#include "idl/results.pb.h"
#include "run_process.h"

namespace gc::cli::testing {
namespace {

namespace v1 = ::gearcoupling::v1;

const CouplingGeometry& upwind() {
  static const CouplingGeometry geometry = codec::load_coupling_geometry(
      std::string(GC_BUNDLED_CATALOG_DIR) + "/nrel_upwind.textproto");
  return geometry;
}

constexpr double kDegree = M_PI / 180.0;

// 1.5 MN·m, 0.4 deg, direction 30 deg, mu 0.1, as the flags below state it.
OperatingPoint nominal_point() { return {1.5e6, 0.4 * kDegree, 30.0 * kDegree, 0.1}; }
const std::vector<std::string> kNominalFlags = {"--torque-nm", "1.5e6", "--misalignment-deg", "0.4",
                                                "--direction-deg", "30"};

std::vector<std::string> with(std::vector<std::string> args, std::vector<std::string> more) {
  args.insert(args.end(), more.begin(), more.end());
  return args;
}

template <typename Message>
Message parse_json(const std::string& json) {
  Message message;
  const auto status = google::protobuf::util::JsonStringToMessage(json, &message);
  EXPECT_TRUE(status.ok()) << status.ToString() << "\n" << json;
  return message;
}

// The value column of the quantity-table row whose quantity starts with `quantity`.
double table_value(const std::string& table, const std::string& quantity) {
  std::istringstream lines(table);
  std::string line;
  while (std::getline(lines, line)) {
    if (line.rfind(quantity, 0) == 0) {
      std::istringstream rest(line.substr(quantity.size()));
      double value = NAN;
      rest >> value;
      return value;
    }
  }
  ADD_FAILURE() << "no row '" << quantity << "' in\n" << table;
  return NAN;
}

TEST(CliContact, TableShowsSummaryAndEveryToothMatchingTheCore) {
  const ProcessResult run = run_gearcoupling(with({"contact"}, kNominalFlags));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const ToothContact core = tooth_contact(upwind(), nominal_point());
  EXPECT_EQ(table_value(run.out, "teeth in contact"), core.teeth_in_contact);
  EXPECT_NEAR(table_value(run.out, "max tooth load"), core.max_tooth_load_n,
              1e-5 * core.max_tooth_load_n);  // tables print six significant digits
  EXPECT_NE(run.out.find("load P_d [N]"), std::string::npos);  // units in the headers
  // One row per tooth: "99  <angle> ..." is the last.
  EXPECT_NE(run.out.find("\n99 "), std::string::npos);
  EXPECT_EQ(run.out.find("nan"), std::string::npos);
}

TEST(CliContact, JsonEqualsTheCoreBitForBit) {
  const ProcessResult run = run_gearcoupling(with({"contact", "--json"}, kNominalFlags));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const auto json = parse_json<v1::ToothContactResult>(run.out);
  const ToothContact core = tooth_contact(upwind(), nominal_point());
  EXPECT_EQ(json.coupling(), "nrel_upwind");
  EXPECT_EQ(json.load_sharing().q(), core.load_sharing.q);
  EXPECT_EQ(json.max_tooth_load_n(), core.max_tooth_load_n);
  ASSERT_EQ(json.teeth_size(), 100);
  for (int j = 0; j < 100; ++j) EXPECT_EQ(json.teeth(j).load_n(), core.teeth[j].load_n) << j;
  EXPECT_EQ(json.operating_point().torque_nm(), 1.5e6);
}

TEST(CliContact, SlicesFlagReachesTheCore) {
  const ProcessResult run =
      run_gearcoupling(with({"contact", "--json", "--slices", "8"}, kNominalFlags));
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(parse_json<v1::ToothContactResult>(run.out).teeth(0).slice_loads_n_size(), 9);
}

TEST(CliMoments, TableAndJsonMatchTheCore) {
  const std::vector<std::string> args = with(with({"moments"}, kNominalFlags), {"--mu", "0.1"});
  const InducedMoments core = induced_moments(upwind(), nominal_point());
  const ProcessResult table = run_gearcoupling(args);
  ASSERT_EQ(table.exit_code, 0) << table.err;
  EXPECT_NEAR(table_value(table.out, "M_y' (eq 46)"), core.moment_y_nm,
              1e-5 * std::abs(core.moment_y_nm));
  const ProcessResult json = run_gearcoupling(with(args, {"--json"}));
  ASSERT_EQ(json.exit_code, 0) << json.err;
  const auto parsed = parse_json<v1::InducedMomentsResult>(json.out);
  EXPECT_EQ(parsed.moment_y_nm(), core.moment_y_nm);
  EXPECT_EQ(parsed.sensor_moment_z_nm(), core.sensor_moment_z_nm);
  EXPECT_EQ(parsed.operating_point().friction_coefficient(), 0.1);
}

TEST(CliJamAngle, TableAndJsonMatchTheCore) {
  const JamAngle& core = upwind().jam_angle();
  const ProcessResult table = run_gearcoupling({"jam-angle"});
  ASSERT_EQ(table.exit_code, 0) << table.err;
  EXPECT_NEAR(table_value(table.out, "jam angle xi (eq 35)"), core.angle_rad / kDegree, 1e-5);
  EXPECT_NE(table.out.find(std::string(to_string(core.governing))), std::string::npos);
  const auto json = parse_json<v1::JamAngleResult>(run_gearcoupling({"jam-angle", "--json"}).out);
  EXPECT_EQ(json.angle_rad(), core.angle_rad);
  EXPECT_EQ(json.governing(), to_string(core.governing));
  EXPECT_EQ(json.radial_deg(), core.radial_rad * 180.0 / M_PI);
}

TEST(CliJamAngle, DownwindFromTheCatalogueDiffersFromUpwind) {
  const auto up = parse_json<v1::JamAngleResult>(run_gearcoupling({"jam-angle", "--json"}).out);
  const auto down = parse_json<v1::JamAngleResult>(
      run_gearcoupling({"jam-angle", "--json", "--coupling", "nrel_downwind"}).out);
  EXPECT_EQ(down.coupling(), "nrel_downwind");
  EXPECT_GT(down.angle_deg(), up.angle_deg());  // Table 3: 1.8 deg downwind vs 0.9 upwind
}

TEST(CliRestoringTorque, TableAndJsonMatchTheCore) {
  const RestoringTorque core = restoring_torque(upwind());
  const ProcessResult table = run_gearcoupling({"restoring-torque"});
  ASSERT_EQ(table.exit_code, 0) << table.err;
  EXPECT_NEAR(table_value(table.out, "restoring torque T_m"), core.torque_nm,
              1e-5 * core.torque_nm);
  const auto json =
      parse_json<v1::RestoringTorqueResult>(run_gearcoupling({"restoring-torque", "--json"}).out);
  EXPECT_EQ(json.torque_nm(), core.torque_nm);
  EXPECT_EQ(json.teeth_in_contact(), core.teeth_in_contact);
}

TEST(CliFriction, TableAndJsonMatchTheCore) {
  const std::vector<std::string> args = {"friction", "--torque-nm", "1.5e6", "--misalignment-deg",
                                         "0.4", "--msy-nm", "-50000", "--msz-nm", "120000"};
  const FrictionEstimate core =
      estimate_friction(upwind(), {1.5e6, 0.4 * kDegree, 0.0, -50000.0, 120000.0});
  const ProcessResult table = run_gearcoupling(args);
  ASSERT_EQ(table.exit_code, 0) << table.err;
  EXPECT_NEAR(table_value(table.out, "friction coefficient mu (eq 4)"),
              core.friction_coefficient, 1e-6);
  const auto json =
      parse_json<v1::FrictionEstimateResult>(run_gearcoupling(with(args, {"--json"})).out);
  EXPECT_EQ(json.friction_coefficient(), core.friction_coefficient);
  EXPECT_EQ(json.measurement().sensor_moment_y_nm(), -50000.0);
}

struct BadInputCase {
  std::vector<std::string> args;
  std::vector<std::string> expected;  // every one must appear in the error line
};

class CliBadInput : public ::testing::TestWithParam<BadInputCase> {};

TEST_P(CliBadInput, ExitsTwoWithOneLineNamingFlagValueAndRange) {
  const ProcessResult run = run_gearcoupling(GetParam().args);
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_TRUE(run.out.empty()) << run.out;
  ASSERT_FALSE(run.err.empty());
  EXPECT_EQ(run.err.find('\n'), run.err.size() - 1) << "not one line: " << run.err;
  for (const std::string& text : GetParam().expected) {
    EXPECT_NE(run.err.find(text), std::string::npos) << "'" << text << "' not in: " << run.err;
  }
}

INSTANTIATE_TEST_SUITE_P(
    Flags, CliBadInput,
    ::testing::Values(
        BadInputCase{{"contact", "--torque-nm", "-5", "--misalignment-deg", "0.4"},
                     {"--torque-nm -5", "operating_point.torque_nm", "allowed (0, 1e12] N·m"}},
        BadInputCase{{"contact", "--torque-nm", "1e6", "--misalignment-deg", "2"},
                     {"--misalignment-deg 2", "jam angle", "0.750906 deg"}},
        BadInputCase{{"moments", "--torque-nm", "1e6", "--misalignment-deg", "0.4", "--mu", "1.5"},
                     {"--mu 1.5", "allowed [0, 1]"}},
        BadInputCase{{"moments", "--torque-nm", "1e6", "--misalignment-deg", "0.4"},
                     {"--mu is required"}},
        BadInputCase{{"contact", "--torque-nm", "abc", "--misalignment-deg", "0.4"},
                     {"--torque-nm 'abc' is not a number"}},
        BadInputCase{{"contact", "--torque-nm", "1e6", "--misalignment-deg", "0.4", "--slices", "3"},
                     {"--slices 3", "even number in [2, 1000]"}},
        BadInputCase{{"moments", "--torque-nm", "1e308", "--misalignment-deg", "0.4", "--mu", "0.1"},
                     {"--torque-nm 1e308", "operating_point.torque_nm", "out of range: allowed"}},
        // Eq 4 divides the moments by the torque: 1e308 / 1e-300 overflows; the core refuses.
        BadInputCase{{"friction", "--torque-nm", "1e-300", "--misalignment-deg", "0.4", "--msy-nm",
                      "1e308", "--msz-nm", "1e308"},
                     {"--torque-nm 1e-300", "(eq 4) is finite"}},
        BadInputCase{{"contact", "--torque-nm", "1e6", "--misalignment-deg", "0.4", "--slices", "x"},
                     {"--slices 'x' is not a whole number"}},
        BadInputCase{{"contact", "--torque-nm", "nan", "--misalignment-deg", "0.4"},
                     {"--torque-nm nan", "allowed (0, 1e12] N·m"}},
        BadInputCase{{"contact", "--torque-nm", "1e6", "--misalignment-deg", "0.4", "--colour", "red"},
                     {"unknown flag --colour"}},
        BadInputCase{{"contact", "--torque-nm", "1e6", "--misalignment-deg", "0.4", "--coupling",
                      "nrel_sideways"},
                     {"--coupling nrel_sideways", "nrel_downwind, nrel_upwind"}},
        // 42 kN·m at 0.4 deg lies on eq 22's root branch, where one step cannot reach the fixed point.
        BadInputCase{{"contact", "--torque-nm", "4.2e4", "--misalignment-deg", "0.4",
                      "--max-iterations", "1"},
                     {"did not reach tolerance", "--max-iterations"}},
        BadInputCase{{"friction", "--torque-nm", "1e6", "--misalignment-deg", "0.4", "--msy-nm", "0",
                      "--msz-nm", "inf"},
                     {"--msz-nm inf", "measurement.sensor_moment_z_nm", "finite"}},
        BadInputCase{{"batch", "--in", "/nonexistent/cases.csv"},
                     {"--in /nonexistent/cases.csv", "cannot open"}},
        BadInputCase{{"spin"}, {"unknown subcommand 'spin'"}}));

TEST(CliCouplingFile, MissingFieldInAUserFileNamesFieldAndFile) {
  const std::string dir = temp_path("gc_user_coupling");
  std::filesystem::create_directories(dir);
  std::istringstream bundled(
      read_file(std::string(GC_BUNDLED_CATALOG_DIR) + "/nrel_upwind.textproto"));
  std::string text, line;
  while (std::getline(bundled, line)) {
    if (line.rfind("facewidth_m", 0) != 0) text += line + "\n";
  }
  write_file(dir + "/mine.textproto", text);
  const ProcessResult run = run_gearcoupling({"jam-angle", "--coupling", dir + "/mine.textproto"});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("coupling.facewidth_m: required field missing in mine.textproto"),
            std::string::npos)
      << run.err;
  std::filesystem::remove_all(dir);
}

TEST(CliCouplingFile, AGivenFileIsUsedInsteadOfTheCatalogue) {
  const ProcessResult run = run_gearcoupling(
      {"jam-angle", "--json", "--coupling",
       std::string(GC_BUNDLED_CATALOG_DIR) + "/nrel_downwind.textproto", "--catalogue",
       "/nonexistent"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(parse_json<v1::JamAngleResult>(run.out).coupling(), "nrel_downwind");
}

class CliHelp : public ::testing::TestWithParam<std::pair<std::string, std::string>> {};

TEST_P(CliHelp, PrintsUsageAndTheSubcommandsFlags) {
  const auto& [subcommand, flag] = GetParam();
  const ProcessResult run = run_gearcoupling({subcommand, "--help"});
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_NE(run.out.find("usage: gearcoupling " + subcommand), std::string::npos) << run.out;
  EXPECT_NE(run.out.find(flag), std::string::npos) << run.out;
}

INSTANTIATE_TEST_SUITE_P(
    Subcommands, CliHelp,
    ::testing::Values(std::pair{"contact", "--misalignment-deg <deg>"},
                      std::pair{"jam-angle", "--coupling"}, std::pair{"moments", "--mu"},
                      std::pair{"restoring-torque", "--catalogue"}, std::pair{"friction", "--msz-nm"},
                      std::pair{"batch", "-j, --jobs"},
                      std::pair{"validate", "-j, --jobs <N>"},
                      std::pair{"diagnose", "alias --threads"},
                      std::pair{"synth", "--sample-period-s <s>"}));

}  // namespace
}  // namespace gc::cli::testing
