// synth and validate run as a user runs them: reproducible bytes, JSON, the HTML report as one
// offline file, and bad input as exit code 2 with the line and column.
#include <regex>

#include <google/protobuf/util/json_util.h>
#include <gtest/gtest.h>

#include "analysis/recording_csv.h"
#include "idl/validation.pb.h"
#include "run_process.h"

namespace gc::cli::testing {
namespace {

using analysis::read_recording;
using analysis::Recording;

const std::string kRecordings = GC_BUNDLED_RECORDINGS_DIR;

TEST(SynthCli, SameSeedGivesTheSameBytesAndAnotherSeedOtherBytes) {
  const std::vector<std::string> args = {"synth", "--model", "paper", "--sequence", "torque-sweep",
                                         "--samples", "300", "--noise-nm", "1500"};
  auto with_seed = [&](const std::string& seed) {
    auto a = args;
    a.insert(a.end(), {"--seed", seed});
    return run_gearcoupling(a);
  };
  const ProcessResult a = with_seed("9"), b = with_seed("9"), c = with_seed("10");
  ASSERT_EQ(a.exit_code, 0) << a.err;
  EXPECT_EQ(a.out, b.out);
  EXPECT_NE(a.out, c.out);
  EXPECT_EQ(a.out.rfind("time_s,torque_nm,misalignment_rad,direction_rad,msy_nm,msz_nm\n", 0), 0u);
}

TEST(SynthCli, BundledRecordingsAreWhatMakeRecordingsProduces) {
  // To rounding: a faster core may change the last bits of a prediction, not the recording.
  const std::string path = temp_path("moment_sweep") + ".csv";
  const ProcessResult run = run_gearcoupling({"synth", "--model", "paper", "--sequence",
      "moment-sweep", "--samples", "1000", "--noise-nm", "2000", "--seed", "1", "--out", path});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const Recording made = read_recording(path);
  const Recording bundled = read_recording(kRecordings + "/paper_moment_sweep.csv");
  ASSERT_EQ(made.samples.size(), bundled.samples.size());
  for (std::size_t i = 0; i < made.samples.size(); ++i) {
    EXPECT_EQ(made.samples[i].input.torque_nm, bundled.samples[i].input.torque_nm);
    EXPECT_NEAR(made.samples[i].measured.y_nm, bundled.samples[i].measured.y_nm, 1e-3) << i;
    EXPECT_NEAR(made.samples[i].measured.z_nm, bundled.samples[i].measured.z_nm, 1e-3) << i;
  }
}

TEST(SynthCli, UnknownSequenceIsABadFlag) {
  const ProcessResult run = run_gearcoupling({"synth", "--model", "paper", "--sequence", "sweep"});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("--sequence 'sweep'"), std::string::npos) << run.err;
}

TEST(ValidateCli, JsonParsesAsAValidationResultAtTheNoiseLevel) {
  const ProcessResult run = run_gearcoupling(
      {"validate", "--data", kRecordings + "/paper_torque_sweep.csv", "--model", "paper", "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  gearcoupling::v1::ValidationResult result;
  ASSERT_TRUE(google::protobuf::util::JsonStringToMessage(run.out, &result).ok()) << run.out;
  EXPECT_EQ(result.recording_rows(), 1000u);
  ASSERT_EQ(result.models_size(), 1);
  const auto& model = result.models(0);
  EXPECT_EQ(model.compared_samples(), 1000u);
  // The bundled recordings carry 2 kN·m of noise (make_recordings.sh).
  EXPECT_NEAR(model.overall().msy().rmse_nm(), 2000.0, 200.0);
  EXPECT_NEAR(model.overall().msz().rmse_nm(), 2000.0, 200.0);
  EXPECT_NEAR(model.overall().msz().rmse_pct(), 100.0 * model.overall().msz().rmse_nm() / 1.5e6, 1e-9);
  ASSERT_EQ(model.signatures_size(), 2);
  EXPECT_TRUE(model.signatures(0).at_noise_level());
  EXPECT_EQ(model.binnings_size(), 5);
}

TEST(ValidateCli, TerminalSummaryNamesTheLowTorqueRegionOfTheHiddenEccentricity) {
  const ProcessResult run = run_gearcoupling(
      {"validate", "--data", kRecordings + "/hidden_eccentricity_torque_ramp.csv", "--model", "paper"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("M_sy' errs most at low torque ("), std::string::npos) << run.out;
  // Engineering units throughout: kN·m columns and regions, no % of T_ref, no exponents.
  EXPECT_NE(run.out.find("reference torque T_ref 1.50 MN·m"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("RMSE [kN·m]"), std::string::npos) << run.out;
  EXPECT_EQ(run.out.find("T_ref]"), std::string::npos) << run.out;
  EXPECT_EQ(run.out.find("of T_ref"), std::string::npos) << run.out;
  EXPECT_EQ(run.out.find("e+0"), std::string::npos) << run.out;
}

TEST(ValidateCli, SamplesBeyondTheJamAngleAreCountedNotDropped) {
  const std::string path = temp_path("beyond_jam") + ".csv";
  write_file(path, "time_s,torque_nm,misalignment_deg,direction_deg,msy_nm,msz_nm\n"
                   "0,1e6,0.1,0,-1e5,1e4\n1,1e6,5,0,-1e5,1e4\n2,1e6,0.2,0,-1e5,1e4\n");
  const ProcessResult run =
      run_gearcoupling({"validate", "--data", path, "--model", "paper", "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  gearcoupling::v1::ValidationResult result;
  ASSERT_TRUE(google::protobuf::util::JsonStringToMessage(run.out, &result).ok());
  EXPECT_EQ(result.models(0).compared_samples(), 2u);
  EXPECT_EQ(result.models(0).rejected_samples(), 1u);
  ASSERT_EQ(result.models(0).rejections_size(), 1);
  EXPECT_EQ(result.models(0).rejections(0).first_time_s(), 1.0);
}

TEST(ValidateCli, MalformedRowsAreListedWithLineAndColumn) {
  const std::string path = temp_path("malformed") + ".csv";
  write_file(path, "time_s,torque_nm,misalignment_deg,direction_deg,msy_nm,msz_nm\n"
                   "0,1e6,0.1,0,-1e5,1e4\n1,1e6,,0,-1e5,1e4\n2,1e6,0.2,0,-1e5,1e4\n");
  const ProcessResult run = run_gearcoupling({"validate", "--data", path, "--model", "paper"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.out.find("1 of 3 rows"), std::string::npos) << run.out;
  EXPECT_NE(run.out.find("line 3, column 3 (misalignment_deg): empty cell"), std::string::npos)
      << run.out;
}

TEST(ValidateCli, MissingColumnIsBadInputNamingIt) {
  const std::string path = temp_path("no_msz") + ".csv";
  write_file(path, "time_s,torque_nm,misalignment_deg,direction_deg,msy_nm\n0,1e6,0.1,0,1\n");
  const ProcessResult run = run_gearcoupling({"validate", "--data", path, "--model", "paper"});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("required column msz missing"), std::string::npos) << run.err;
}

TEST(ValidateCli, ModelFileErrorIsBadInputNamingFieldAndFile) {
  const std::string model = temp_path("bad_model") + ".textproto";
  write_file(model, "coupling: \"nrel_upwind\"\neffects { name: \"friction\" parameters { name: "
                    "\"mu0\" value: -0.1 } }\n");
  const ProcessResult run = run_gearcoupling(
      {"validate", "--data", kRecordings + "/paper_torque_ramp.csv", "--model", model});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_NE(run.err.find("model.effects[0].friction.mu0"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("bad_model"), std::string::npos) << run.err;
}

TEST(ValidateCli, ResultDoesNotDependOnTheThreadCount) {
  const std::vector<std::string> args = {"validate", "--data",
      kRecordings + "/paper_moment_sweep.csv", "--model", "paper", "--json"};
  auto with_threads = [&](const std::string& threads) {
    auto a = args;
    a.insert(a.end(), {"-j", threads});
    return run_gearcoupling(a);
  };
  const ProcessResult one = with_threads("1"), three = with_threads("3");
  ASSERT_EQ(one.exit_code, 0) << one.err;
  EXPECT_EQ(one.out, three.out);
}

TEST(ValidateCli, HtmlReportIsOneFileWithChartJsInlinedAndNothingFetched) {
  const std::string html = temp_path("report") + ".html";
  const ProcessResult run = run_gearcoupling({"validate", "--data",
      kRecordings + "/hidden_eccentricity_torque_ramp.csv", "--model", "paper", "--html", html});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  const std::string page = read_file(html);
  EXPECT_NE(page.find("Chart.js v3."), std::string::npos);   // the library's own banner
  EXPECT_NE(page.find("new Chart("), std::string::npos);
  EXPECT_NE(page.find("errs most at low torque"), std::string::npos);
  // Nothing the browser would fetch: no src/href to another place, no CSS imports or urls.
  EXPECT_FALSE(std::regex_search(page, std::regex(R"((src|href)\s*=)", std::regex::icase)));
  EXPECT_EQ(page.find("@import"), std::string::npos);
  EXPECT_EQ(page.find("url("), std::string::npos);
  EXPECT_EQ(page.find("<link"), std::string::npos);
}

}  // namespace
}  // namespace gc::cli::testing
