// diagnose and validate --add run as a user runs them, on the bundled recordings
// (data/recordings/make_recordings.sh): find the hidden effect, write the model with it, and
// watch the error fall to the noise.
#include <algorithm>
#include <cstdio>
#include <numbers>

#include <google/protobuf/util/json_util.h>
#include <gtest/gtest.h>

#include "idl/diagnosis.pb.h"
#include "idl/validation.pb.h"
#include "run_process.h"

namespace gc::cli::testing {
namespace {

const std::string kRecordings = GC_BUNDLED_RECORDINGS_DIR;
const std::string kHidden = kRecordings + "/hidden_eccentricity_torque_ramp.csv";
constexpr double kNoiseNm = 2000.0;  // make_recordings.sh: --noise-nm 2000

template <typename Message>
Message parse(const ProcessResult& run) {
  Message message;
  EXPECT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(google::protobuf::util::JsonStringToMessage(run.out, &message).ok()) << run.out;
  return message;
}

double parameter(const gearcoupling::v1::ParameterSetRecord& set, const std::string& name) {
  for (const auto& p : set.parameters()) if (p.name() == name) return p.value();
  ADD_FAILURE() << "no parameter " << name;
  return 0.0;
}

TEST(DiagnoseCli, FindsTheBundledHiddenEccentricityAndThenOnlyNoise) {
  const auto result = parse<gearcoupling::v1::DiagnosisResult>(
      run_gearcoupling({"diagnose", "--data", kHidden, "--model", "paper", "--json"}));
  ASSERT_EQ(result.rounds_size(), 2) << result.summary();
  EXPECT_EQ(result.rounds(0).outcome(), "effect_found");
  EXPECT_EQ(result.rounds(0).ranking(0).effect(), "eccentricity");
  EXPECT_EQ(result.rounds(0).claimed().effect(), "eccentricity");
  // hidden_eccentricity.truth.textproto: 0.0015 rad, the default threshold 1 and direction pi/2.
  EXPECT_NEAR(parameter(result.rounds(0).claimed(), "eccentric_misalignment_rad"), 0.0015, 0.0015 * 0.05);
  EXPECT_NEAR(parameter(result.rounds(0).claimed(), "threshold_scale"), 1.0, 0.05);
  EXPECT_NEAR(parameter(result.rounds(0).claimed(), "gravity_direction_rad"), std::numbers::pi / 2, 0.05);
  EXPECT_EQ(result.rounds(1).outcome(), "noise");
  EXPECT_NEAR(result.rounds(1).rmse_nm(), kNoiseNm, 0.1 * kNoiseNm);
  // The ready-to-paste --add, with the fitted values, brings validate to the noise level.
  ASSERT_EQ(result.add_flags_size(), 1);
  EXPECT_EQ(result.add_flags(0).rfind("eccentricity=eccentric_misalignment_rad=", 0), 0u)
      << result.add_flags(0);
  const auto validated = parse<gearcoupling::v1::ValidationResult>(run_gearcoupling(
      {"validate", "--data", kHidden, "--model", "paper", "--add", result.add_flags(0), "--json"}));
  ASSERT_EQ(validated.models_size(), 2);
  EXPECT_NEAR(validated.models(1).overall().msy().rmse_nm(), kNoiseNm, 0.1 * kNoiseNm);
}

// Issue 22, a time structure: the bundled recording whose moment channels are 0.25 s late
// (hidden_daq_skew.truth.textproto). The delay is found with its time, added with validate --add,
// and the error falls to the noise; the JSON's row counts agree with the text's.
TEST(DiagnoseCli, FindsTheBundledDaqSkewWithItsTimeAndTheErrorFallsToTheNoise) {
  const std::string skew = kRecordings + "/hidden_daq_skew_torque_ramp.csv";
  const auto result = parse<gearcoupling::v1::DiagnosisResult>(
      run_gearcoupling({"diagnose", "--data", skew, "--model", "paper", "--json"}));
  ASSERT_GE(result.rounds_size(), 2) << result.summary();
  EXPECT_EQ(result.rounds(0).outcome(), "effect_found");
  EXPECT_EQ(result.rounds(0).claimed().effect(), "moment_delay");
  EXPECT_NEAR(parameter(result.rounds(0).claimed(), "delay_s"), 0.25, 0.01);
  EXPECT_EQ(result.rounds(1).outcome(), "noise");
  EXPECT_EQ(result.malformed_rows(), 0u);
  EXPECT_EQ(result.excluded_rows(), result.malformed_rows() + result.refused_rows());
  ASSERT_EQ(result.add_flags_size(), 1);
  EXPECT_EQ(result.add_flags(0).rfind("moment_delay=delay_s=0.2", 0), 0u) << result.add_flags(0);
  const auto validated = parse<gearcoupling::v1::ValidationResult>(run_gearcoupling(
      {"validate", "--data", skew, "--model", "paper", "--add", result.add_flags(0), "--json"}));
  ASSERT_EQ(validated.models_size(), 2);
  EXPECT_GT(validated.models(0).overall().msy().rmse_nm(), 1.5 * kNoiseNm);
  EXPECT_NEAR(validated.models(1).overall().msy().rmse_nm(), kNoiseNm, 0.1 * kNoiseNm);
}

// Issue 22, class 5: a file with malformed rows gives the same counts in the JSON and the text.
TEST(DiagnoseCli, JsonAndTextGiveTheSameRowCounts) {
  const std::string path = ::testing::TempDir() + "/malformed.csv";
  {
    std::FILE* in = std::fopen(kHidden.c_str(), "r");
    std::FILE* out = std::fopen(path.c_str(), "w");
    ASSERT_TRUE(in && out);
    char line[4096];
    int n = 0;
    while (std::fgets(line, sizeof line, in)) {
      std::fputs(line, out);
      if (++n % 100 == 50) std::fputs("not-a-time,1e5,0,0,0,0\n", out);  // 10 malformed rows
    }
    std::fclose(in);
    std::fclose(out);
  }
  const auto result = parse<gearcoupling::v1::DiagnosisResult>(
      run_gearcoupling({"diagnose", "--data", path, "--model", "paper", "--json"}));
  EXPECT_EQ(result.malformed_rows(), 10u);
  EXPECT_EQ(result.recording_rows(), 1010u);
  EXPECT_EQ(result.excluded_rows(), 10u + result.refused_rows());
  const ProcessResult text = run_gearcoupling({"diagnose", "--data", path, "--model", "paper"});
  ASSERT_EQ(text.exit_code, 0) << text.err;
  EXPECT_NE(text.out.find("1010 rows (10 malformed, 0 refused by the model)"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("10 malformed rows of the file excluded"), std::string::npos) << text.out;
}

TEST(DiagnoseCli, TerminalVerdictNamesTheEffectAndTheFall) {
  const ProcessResult run = run_gearcoupling({"diagnose", "--data", kHidden, "--model", "paper"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("is explained by eccentricity"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("held-out RMSE falls"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("the residual is noise"), std::string::npos) << run.out;
  // Fitted values in engineering notation, the standard error under the value's prefix.
  EXPECT_NE(run.out.find("eccentric_misalignment_rad = 1."), std::string::npos) << run.out;
  EXPECT_NE(run.out.find(" mrad +/- 0."), std::string::npos) << run.out;
  EXPECT_EQ(run.out.find("e+0"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("To validate with it: gearcoupling validate --data " + kHidden +
                         " --model paper --add eccentricity=eccentric_misalignment_rad="),
            std::string::npos)
      << run.out;
}

TEST(ValidateAddCli, AnEffectTheModelHasIsRefusedWhenUnchangedAndNotedWhenReplaced) {
  // data/models/paper.textproto has friction with mu0 = 0.1.
  const ProcessResult same = run_gearcoupling(
      {"validate", "--data", kHidden, "--model", "paper", "--add", "friction=mu0=0.1"});
  EXPECT_EQ(same.exit_code, 2);
  EXPECT_NE(same.err.find("model paper already has friction with these parameters"),
            std::string::npos) << same.err;
  const ProcessResult other = run_gearcoupling(
      {"validate", "--data", kHidden, "--model", "paper", "--add", "friction=mu0=0.12", "--json"});
  ASSERT_EQ(other.exit_code, 0) << other.err;
  EXPECT_NE(other.err.find("note: model paper already has friction (friction=mu0=0.1"),
            std::string::npos) << other.err;
  EXPECT_NE(other.err.find("--add replaces it with friction=mu0=0.12"), std::string::npos)
      << other.err;
  const auto result = parse<gearcoupling::v1::ValidationResult>(other);
  ASSERT_EQ(result.models_size(), 2);
  EXPECT_EQ(result.models(1).model(), "paper, friction replaced");
}

TEST(DiagnoseCli, ClaimsNothingOnARecordingOfTheModelItself) {
  const auto result = parse<gearcoupling::v1::DiagnosisResult>(run_gearcoupling(
      {"diagnose", "--data", kRecordings + "/paper_moment_sweep.csv", "--model", "paper", "--json"}));
  ASSERT_EQ(result.rounds_size(), 1);
  EXPECT_EQ(result.rounds(0).outcome(), "noise");
}

TEST(DiagnoseCli, WrittenModelValidatesAtTheNoiseLevel) {
  const std::string model = temp_path("diagnosed") + ".textproto";
  ASSERT_EQ(run_gearcoupling({"diagnose", "--data", kHidden, "--model", "paper", "--write-model", model}).exit_code, 0);
  const auto result = parse<gearcoupling::v1::ValidationResult>(
      run_gearcoupling({"validate", "--data", kHidden, "--model", model, "--json"}));
  ASSERT_EQ(result.models_size(), 1);
  EXPECT_NEAR(result.models(0).overall().msy().rmse_nm(), kNoiseNm, 0.1 * kNoiseNm);
  EXPECT_NEAR(result.models(0).overall().msz().rmse_nm(), kNoiseNm, 0.1 * kNoiseNm);
}

TEST(ValidateAddCli, ShowsBeforeAndAfterWithTheErrorFalling) {
  const std::vector<std::string> args = {"validate", "--data", kHidden, "--model", "paper", "--add",
                                         "eccentricity=eccentric_misalignment_rad=0.0015"};
  auto json_args = args;
  json_args.push_back("--json");
  const auto result = parse<gearcoupling::v1::ValidationResult>(run_gearcoupling(json_args));
  ASSERT_EQ(result.models_size(), 2);
  EXPECT_EQ(result.models(1).model(), "paper + eccentricity");
  EXPECT_LT(result.models(1).overall().msy().rmse_nm(), 0.5 * result.models(0).overall().msy().rmse_nm());
  EXPECT_NEAR(result.models(1).overall().msy().rmse_nm(), kNoiseNm, 0.1 * kNoiseNm);
  const ProcessResult table = run_gearcoupling(args);
  ASSERT_EQ(table.exit_code, 0) << table.err;
  EXPECT_NE(table.out.find("Before (paper) and after (paper + eccentricity)"), std::string::npos) << table.out;
}

TEST(ValidateAddCli, BadEffectSpecsAreBadInputNamingTheField) {
  const auto run_add = [](const std::string& spec) {
    return run_gearcoupling({"validate", "--data", kHidden, "--model", "paper", "--add", spec});
  };
  const ProcessResult unknown = run_add("teleportation");
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_NE(unknown.err.find("effects.teleportation"), std::string::npos) << unknown.err;
  const ProcessResult out_of_range = run_add("hysteresis=lag_rad=1");
  EXPECT_EQ(out_of_range.exit_code, 2);
  EXPECT_NE(out_of_range.err.find("effects.hysteresis.lag_rad"), std::string::npos) << out_of_range.err;
  const ProcessResult not_a_number = run_add("hysteresis=lag_rad=much");
  EXPECT_EQ(not_a_number.exit_code, 2);
  EXPECT_NE(not_a_number.err.find("lag_rad=much"), std::string::npos) << not_a_number.err;
}

// docs/tutorial.md, part 2: a moment outside the library, a formula proposed, written to the
// model file, read back, and added by --add; the error falls to the noise both ways.
TEST(DiagnoseCli, ProposesTheFormulaForTheBundledLoadingFrictionAndItValidatesAtTheNoise) {
  const std::string recording = kRecordings + "/hidden_loading_friction_moment_sweep.csv";
  const std::string model = temp_path("formula") + ".textproto";
  const auto result = parse<gearcoupling::v1::DiagnosisResult>(run_gearcoupling(
      {"diagnose", "--data", recording, "--model", "paper", "--json", "--write-model", model}));
  ASSERT_EQ(result.rounds_size(), 2) << result.summary();
  EXPECT_EQ(result.rounds(0).outcome(), "formula_proposed");
  EXPECT_TRUE(result.rounds(0).formula_chosen());
  EXPECT_EQ(result.rounds(0).formula().kind(), "formula");
  EXPECT_EQ(result.rounds(0).claimed().effect(), "expression");
  // hidden_loading_friction.truth.textproto: 6000 N·m.
  EXPECT_NEAR(parameter(result.rounds(0).claimed(), "travel_sign_along_misalignment"), 6000.0, 300.0);
  EXPECT_NE(result.rounds(0).verdict().find("Coulomb friction in the loading mechanism"), std::string::npos);
  EXPECT_EQ(result.rounds(1).outcome(), "noise");

  const auto written = parse<gearcoupling::v1::ValidationResult>(
      run_gearcoupling({"validate", "--data", recording, "--model", model, "--json"}));
  ASSERT_EQ(written.models_size(), 1);
  EXPECT_NEAR(written.models(0).overall().msy().rmse_nm(), kNoiseNm, 0.1 * kNoiseNm);
  const auto added = parse<gearcoupling::v1::ValidationResult>(run_gearcoupling(
      {"validate", "--data", recording, "--model", "paper", "--add", "expression=travel_sign_along_misalignment=5875", "--json"}));
  ASSERT_EQ(added.models_size(), 2);
  EXPECT_GT(added.models(0).overall().msy().rmse_nm(), 2.5 * kNoiseNm);
  EXPECT_NEAR(added.models(1).overall().msy().rmse_nm(), kNoiseNm, 0.1 * kNoiseNm);
  const ProcessResult unknown_term = run_gearcoupling(
      {"validate", "--data", recording, "--model", "paper", "--add", "expression=travel_sign_along_w=1"});
  EXPECT_EQ(unknown_term.exit_code, 2);
  EXPECT_NE(unknown_term.err.find("effects.expression.travel_sign_along_w"), std::string::npos) << unknown_term.err;
}

}  // namespace
}  // namespace gc::cli::testing

namespace gc::cli::testing {
namespace {

/// `text` written to a file in the test's temporary directory; its path.
std::string write_temp(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + "/" + name;
  std::FILE* out = std::fopen(path.c_str(), "w");
  EXPECT_TRUE(out);
  std::fputs(text.c_str(), out);
  std::fclose(out);
  return path;
}

/// The bundled hidden-eccentricity recording with the torque negated from data row `from` on.
std::string torque_negated_from(std::size_t from) {
  std::FILE* in = std::fopen(kHidden.c_str(), "r");
  EXPECT_TRUE(in);
  std::string text;
  char line[4096];
  for (std::size_t n = 0; std::fgets(line, sizeof line, in); ++n) {
    std::string row = line;
    const std::size_t comma = row.find(',');
    if (n >= from + 1) row.insert(comma + 1, "-");  // torque is the second column
    text += row;
  }
  std::fclose(in);
  return write_temp("negative_torque.csv", text);
}

TEST(DiagnoseCli, ATorqueTurningNegativePartwayIsCountedAndAdvisedNotCalledNoise) {
  const std::string path = torque_negated_from(600);
  const auto result = parse<gearcoupling::v1::DiagnosisResult>(
      run_gearcoupling({"diagnose", "--data", path, "--model", "paper", "--json"}));
  EXPECT_EQ(result.refused_rows(), 400u);
  bool found = false;
  for (const auto& f : result.data_quality()) {
    if (f.kind() != "polarity_flip" || f.channel() != "torque") continue;
    found = true;
    EXPECT_EQ(f.rows(), 400u);
    EXPECT_EQ(f.first_row(), 600u);
    EXPECT_EQ(f.last_row(), 999u);
    EXPECT_TRUE(f.excluded());
    EXPECT_NE(f.detail().find("400 of 1000 rows"), std::string::npos) << f.detail();
    EXPECT_NE(f.detail().find("--negate torque"), std::string::npos) << f.detail();
  }
  EXPECT_TRUE(found);
  ASSERT_EQ(result.excluded_ranges_size(), 1);
  EXPECT_EQ(result.excluded_ranges(0).span().first_row(), 600u);
  EXPECT_EQ(result.excluded_ranges(0).span().last_row(), 999u);
  EXPECT_NE(result.excluded_ranges(0).reason().find("polarity_flip torque"), std::string::npos);
  const ProcessResult text = run_gearcoupling({"diagnose", "--data", path, "--model", "paper"});
  ASSERT_EQ(text.exit_code, 0) << text.err;
  const std::size_t paragraph = text.out.find("Data quality (before the physics):");
  ASSERT_NE(paragraph, std::string::npos) << text.out;
  EXPECT_LT(paragraph, text.out.find("Round 1")) << text.out;
  EXPECT_NE(text.out.find("torque polarity_flip: the torque is negative on 400 of 1000 rows"), std::string::npos) << text.out;
}

TEST(DiagnoseCli, ToValidateLineNamesTheModelFileGivenWithSixDigitValues) {
  std::FILE* in = std::fopen((std::string(GC_BUNDLED_RECORDINGS_DIR) + "/../models/paper.textproto").c_str(), "r");
  ASSERT_TRUE(in);
  std::string model_text;
  char line[4096];
  while (std::fgets(line, sizeof line, in)) model_text += line;
  std::fclose(in);
  const std::string model = write_temp("case_04.textproto", model_text);
  const ProcessResult run = run_gearcoupling({"diagnose", "--data", kHidden, "--model", model});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string prefix = "To validate with it: gearcoupling validate --data " + kHidden + " --model " + model + " --add ";
  const std::size_t at = run.out.find(prefix);
  ASSERT_NE(at, std::string::npos) << run.out;
  const std::string add = run.out.substr(at + prefix.size(), run.out.find('\n', at) - at - prefix.size());
  // Every value (after the last '=' of each comma-separated item) has at most 6 significant digits.
  for (std::size_t from = 0; from <= add.size();) {
    const std::size_t comma = std::min(add.find(',', from), add.size());
    const std::string item = add.substr(from, comma - from);
    const std::string value = item.substr(item.rfind('=') + 1);
    std::size_t digits = 0;
    bool leading = true;
    for (char c : value.substr(0, value.find_first_of("eE"))) {
      if (c < '0' || c > '9') continue;
      if (c != '0') leading = false;
      if (!leading) ++digits;
    }
    EXPECT_LE(digits, 6u) << value << " in " << add;
    from = comma + 1;
  }
  // Pasted as printed, it runs.
  const ProcessResult pasted = run_gearcoupling({"validate", "--data", kHidden, "--model", model, "--add", add});
  EXPECT_EQ(pasted.exit_code, 0) << pasted.err;
}

TEST(ValidateCli, ReferenceTorqueIsTheModelFilesFrictionUnlessGiven) {
  const std::string model = write_temp(
      "small_tref.textproto",
      "name: \"small_tref\"\ncoupling: \"nrel_upwind\"\n"
      "effects { name: \"friction\" parameters { name: \"mu0\" value: 0.1 } parameters { name: \"reference_torque_nm\" value: 3e5 } }\n"
      "effects { name: \"pressure_angle_rotation\" }\neffects { name: \"self_weight\" }\n");
  const auto defaulted = parse<gearcoupling::v1::ValidationResult>(
      run_gearcoupling({"validate", "--data", kHidden, "--model", model, "--json"}));
  EXPECT_DOUBLE_EQ(defaulted.reference_torque_nm(), 3e5);
  const auto given = parse<gearcoupling::v1::ValidationResult>(
      run_gearcoupling({"validate", "--data", kHidden, "--model", model, "--json", "--reference-torque-nm", "2e6"}));
  EXPECT_DOUBLE_EQ(given.reference_torque_nm(), 2e6);
}

}  // namespace
}  // namespace gc::cli::testing
