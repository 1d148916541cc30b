// What a measurement engineer hit, run as a user runs it: a DAQ export's other channels and
// names, units in any case, unit slips that gave wrong results in silence, zero compared
// samples read as a perfect fit, counts as JSON strings, and a failed --html left behind.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include <google/protobuf/util/json_util.h>
#include <gtest/gtest.h>

#include "idl/validation.pb.h"
#include "run_process.h"

namespace gc::cli::testing {
namespace {

namespace v1 = ::gearcoupling::v1;

const std::string kRecordings = GC_BUNDLED_RECORDINGS_DIR;
const std::string kSweep = kRecordings + "/paper_torque_sweep.csv";

// The bundled torque sweep under another header line.
std::string with_header(const std::string& header, const std::string& suffix = "") {
  std::ifstream in(kSweep);
  std::string line, text = header + "\n";
  std::getline(in, line);
  while (std::getline(in, line)) text += line + suffix + "\n";
  const std::string path = temp_path("gc_recording") + ".csv";
  write_file(path, text);
  return path;
}

v1::ValidationResult validate_json(const std::vector<std::string>& extra, ProcessResult& run) {
  std::vector<std::string> args = {"validate", "--model", "paper", "--json"};
  args.insert(args.end(), extra.begin(), extra.end());
  run = run_gearcoupling(args);
  v1::ValidationResult result;
  EXPECT_TRUE(google::protobuf::util::JsonStringToMessage(run.out, &result).ok()) << run.out << run.err;
  return result;
}

TEST(RecordingInputCli, NewtonMetresUnderAKnmHeaderAreRefusedWithTheWarningsAdvice) {
  // 1000 times the model: an R² of -3e7 and a gain at its bound were printed as results before.
  const std::string slipped =
      with_header("time_s,torque_nm,misalignment_rad,direction_rad,msy_knm,msz_knm");
  for (const std::string subcommand : {"validate", "diagnose"}) {
    const ProcessResult run =
        run_gearcoupling({subcommand, "--data", slipped, "--model", "paper"});
    EXPECT_EQ(run.exit_code, 2) << subcommand << run.out << run.err;
    EXPECT_EQ(run.out, "") << subcommand;
    EXPECT_NE(run.err.find("gearcoupling " + subcommand + ": warning: M_sy'"), std::string::npos)
        << run.err;
    EXPECT_NE(run.err.find("gearcoupling " + subcommand + ": error: recording: " + slipped +
                           ": unit error: M_sy' measured RMS"),
              std::string::npos) << run.err;
    EXPECT_NE(run.err.find("check the unit of the msy column (N·m under _knm? kN·m under _nm?); "
                           "a fit to moments 1000 times off says nothing: give the column its unit "
                           "(rename it in the file, or --columns msy_knm=HEADER), or --force-scale "
                           "to run anyway"),
              std::string::npos) << run.err;
  }
}

TEST(RecordingInputCli, KilonewtonMetresUnderAnNmHeaderAreRefusedToo) {
  // The issue's case, the other way round: kN·m numbers under _nm, 1000 times too small.
  std::ifstream in(kSweep);
  std::string line, text = "time_s,torque_nm,misalignment_rad,direction_rad,msy_nm,msz_nm\n";
  std::getline(in, line);
  while (std::getline(in, line)) {
    std::vector<std::string> fields;
    std::stringstream row(line);
    for (std::string field; std::getline(row, field, ',');) fields.push_back(field);
    for (std::size_t i = 4; i < 6; ++i) fields[i] = std::to_string(std::stod(fields[i]) / 1000.0);
    text += fields[0] + "," + fields[1] + "," + fields[2] + "," + fields[3] + "," + fields[4] + "," +
            fields[5] + "\n";
  }
  const std::string path = temp_path("gc_knm_under_nm") + ".csv";
  write_file(path, text);
  const ProcessResult run = run_gearcoupling({"validate", "--data", path, "--model", "paper"});
  EXPECT_EQ(run.exit_code, 2) << run.out << run.err;
  EXPECT_NE(run.err.find("too small by about 1000"), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("--force-scale to run anyway"), std::string::npos) << run.err;
}

// Issue 39: torque in kN·m under torque_nm drew only the model's "light torque near the jam
// angle is outside eq 22's range"; now a warning names the unit before that error.
TEST(RecordingInputCli, KilonewtonMetresOfTorqueUnderAnNmHeaderAreNamedAsAUnitSlip) {
  std::ifstream in(kSweep);
  std::string line, text;
  std::getline(in, line);
  text = line + "\n";
  while (std::getline(in, line)) {
    const std::size_t first = line.find(','), second = line.find(',', first + 1);
    const double torque_nm = std::stod(line.substr(first + 1, second - first - 1));
    text += line.substr(0, first + 1) + std::to_string(torque_nm / 1000.0) + line.substr(second) + "\n";
  }
  const std::string path = temp_path("gc_torque_knm") + ".csv";
  write_file(path, text);
  const ProcessResult run = run_gearcoupling({"validate", "--data", path, "--model", "paper"});
  EXPECT_NE(run.exit_code, 0) << run.out << run.err;
  EXPECT_NE(run.err.find("gearcoupling validate: warning: torque reaches only "), std::string::npos) << run.err;
  EXPECT_NE(run.err.find("kN·m under a _nm header? (1000 times too small"), std::string::npos) << run.err;
}

// Issue 39, rough edges: a column named without its unit, a missing file, a misspelt model.
TEST(RecordingInputCli, AColumnWithoutItsUnitAMissingFileAndAMisspeltModelSayWhatIsWrong) {
  const std::string no_unit = with_header("time_s,torque_nm,misalignment_rad,direction_rad,msy,msz_nm");
  const ProcessResult unitless = run_gearcoupling({"validate", "--data", no_unit, "--model", "paper"});
  EXPECT_EQ(unitless.exit_code, 2) << unitless.err;
  EXPECT_NE(unitless.err.find("required column msy missing"), std::string::npos) << unitless.err;
  EXPECT_NE(unitless.err.find("column 5 'msy' has no unit: name it msy_nm"), std::string::npos) << unitless.err;
  const ProcessResult missing = run_gearcoupling({"validate", "--data", "/nonexistent/rec.csv", "--model", "paper"});
  EXPECT_EQ(missing.exit_code, 2) << missing.err;
  EXPECT_NE(missing.err.find("cannot read recording /nonexistent/rec.csv: No such file or directory"),
            std::string::npos) << missing.err;
  const ProcessResult misspelt = run_gearcoupling({"validate", "--data", kSweep, "--model", "papr"});
  EXPECT_EQ(misspelt.exit_code, 2) << misspelt.err;
  EXPECT_NE(misspelt.err.find("--model 'papr': no such bundled model (paper, paper_downwind) nor a "
                             ".textproto file; did you mean 'paper'?"),
            std::string::npos) << misspelt.err;
  const ProcessResult unwritable = run_gearcoupling(
      {"synth", "--model", "paper", "--out", "/nonexistent/dir/out.csv"});
  EXPECT_EQ(unwritable.exit_code, 1) << unwritable.err;
  EXPECT_NE(unwritable.err.find("cannot write --out /nonexistent/dir/out.csv: No such file or directory"),
            std::string::npos) << unwritable.err;
  const ProcessResult effect = run_gearcoupling({"validate", "--data", kSweep, "--model", "paper",
                                                 "--add", "eccentricty"});
  EXPECT_EQ(effect.exit_code, 2) << effect.err;
  EXPECT_NE(effect.err.find("unknown effect; the library has: "), std::string::npos) << effect.err;
  EXPECT_NE(effect.err.find("; did you mean 'eccentricity'?"), std::string::npos) << effect.err;
  const ProcessResult coupling = run_gearcoupling({"jam-angle", "--coupling", "nrel_dowwind"});
  EXPECT_EQ(coupling.exit_code, 2) << coupling.err;
  EXPECT_NE(coupling.err.find("(known: nrel_downwind, nrel_upwind); did you mean 'nrel_downwind'?"),
            std::string::npos) << coupling.err;
}

// A dyno that logs the drive torque negative: refused with what to do, and --negate torque reads
// the same recording as the positive one.
TEST(RecordingInputCli, NegativeTorqueIsRefusedWithTheHintAndNegateTorqueReadsIt) {
  std::ifstream in(kSweep);
  std::string line, text;
  std::getline(in, line);
  text = line + "\n";
  while (std::getline(in, line)) {
    const std::size_t first = line.find(','), second = line.find(',', first + 1);
    text += line.substr(0, first + 1) + "-" + line.substr(first + 1, second - first - 1) +
            line.substr(second) + "\n";
  }
  const std::string negative = temp_path("gc_negative_torque") + ".csv";
  write_file(negative, text);
  const ProcessResult refused = run_gearcoupling({"validate", "--data", negative, "--model", "paper"});
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.err.find("the model refused all 1000 samples read (first: operating_point.torque_nm"),
            std::string::npos) << refused.err;
  EXPECT_NE(refused.err.find("; the model takes the torque as a magnitude (T > 0): for a dyno that "
                             "logs the drive torque negative, read the column with --negate torque"),
            std::string::npos) << refused.err;

  ProcessResult negated, plain;
  const v1::ValidationResult flipped = validate_json({"--data", negative, "--negate", "torque"}, negated);
  const v1::ValidationResult original = validate_json({"--data", kSweep}, plain);
  ASSERT_EQ(negated.exit_code, 0) << negated.err;
  ASSERT_EQ(flipped.models_size(), 1);
  EXPECT_EQ(flipped.models(0).compared_samples(), 1000u);
  EXPECT_EQ(flipped.models(0).SerializeAsString(), original.models(0).SerializeAsString());

  const ProcessResult unknown =
      run_gearcoupling({"validate", "--data", negative, "--model", "paper", "--negate", "torq"});
  EXPECT_EQ(unknown.exit_code, 2);
  EXPECT_NE(unknown.err.find("--negate 'torq': 'torq' is no quantity of docs/recordings.md"),
            std::string::npos) << unknown.err;
  const ProcessResult absent =
      run_gearcoupling({"validate", "--data", negative, "--model", "paper", "--negate", "speed"});
  EXPECT_EQ(absent.exit_code, 2);
  EXPECT_NE(absent.err.find("--negate speed: the header has no speed column"), std::string::npos)
      << absent.err;
}

TEST(RecordingInputCli, ForceScaleRunsAnywayAndTheJsonKeepsTheWarning) {
  ProcessResult run;
  const v1::ValidationResult result = validate_json(
      {"--data", with_header("time_s,torque_nm,misalignment_rad,direction_rad,msy_knm,msz_knm"),
       "--force-scale"}, run);
  EXPECT_EQ(run.exit_code, 0) << run.err;
  ASSERT_GE(result.warnings_size(), 1) << run.out;
  EXPECT_NE(result.warnings(0).find("M_sy'"), std::string::npos) << result.warnings(0);
  EXPECT_NE(result.warnings(0).find("by about 1000"), std::string::npos) << result.warnings(0);
  EXPECT_NE(run.err.find("gearcoupling validate: warning: M_sy'"), std::string::npos) << run.err;
  // The same recording with its own header: no warning at all.
  ProcessResult plain;
  EXPECT_EQ(validate_json({"--data", kSweep}, plain).warnings_size(), 0);
  EXPECT_EQ(plain.err, "");
}

TEST(RecordingInputCli, RadiansUnderADegHeaderAreWarned) {
  ProcessResult run;
  const v1::ValidationResult result = validate_json(
      {"--data", with_header("time_s,torque_nm,misalignment_deg,direction_rad,msy_nm,msz_nm")}, run);
  EXPECT_EQ(run.exit_code, 0) << run.err;
  bool found = false;
  for (const std::string& warning : result.warnings()) found |= warning.find("radians under a _deg header") != std::string::npos;
  EXPECT_TRUE(found) << run.out;
  EXPECT_NE(run.err.find("radians under a _deg header"), std::string::npos) << run.err;
}

TEST(RecordingInputCli, UnknownColumnsAreIgnoredWithANoteAndColumnsRenames) {
  ProcessResult original;
  const v1::ValidationResult expected = validate_json({"--data", kSweep}, original);
  ProcessResult run;
  const v1::ValidationResult result = validate_json(
      {"--data", with_header("time_s,torque_nm,misalignment_rad,direction_rad,Ch3_kNm,msz_nm,Ch9,Ch10", ",7,x"),
       "--columns", "msy_nm=Ch3_kNm"}, run);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_NE(run.err.find("note: ignored 2 columns of no known quantity: Ch9, Ch10"), std::string::npos) << run.err;
  ASSERT_EQ(result.ignored_columns_size(), 2);
  EXPECT_EQ(result.ignored_columns(1), "Ch10");
  EXPECT_EQ(result.models(0).overall().msy().rmse_nm(), expected.models(0).overall().msy().rmse_nm());
  EXPECT_EQ(result.models(0).compared_samples(), 1000u);
}

TEST(RecordingInputCli, UnitsInAnyCaseReadAsTheListedOnes) {
  ProcessResult original, run;
  const v1::ValidationResult expected = validate_json({"--data", kSweep}, original);
  const v1::ValidationResult result = validate_json(
      {"--data", with_header("time_S,torque_Nm,misalignment_RAD,direction_rad,msy_Nm,msz_NM")}, run);
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_EQ(result.models(0).overall().msz().rmse_nm(), expected.models(0).overall().msz().rmse_nm());
}

TEST(RecordingInputCli, AHeaderOnlyFileIsAnErrorNotAPerfectFit) {
  const std::string path = temp_path("gc_header_only") + ".csv";
  write_file(path, "time_s,torque_nm,misalignment_rad,direction_rad,msy_nm,msz_nm\n");
  for (const std::string subcommand : {"validate", "diagnose"}) {
    const ProcessResult run = run_gearcoupling({subcommand, "--data", path, "--model", "paper"});
    EXPECT_EQ(run.exit_code, 2) << subcommand;
    EXPECT_EQ(run.out, "") << subcommand;
    EXPECT_NE(run.err.find("paper compared no sample: the file has no data rows"), std::string::npos) << run.err;
  }
}

TEST(RecordingInputCli, EverySampleBeyondTheJamAngleIsAnErrorNamingTheReason) {
  const std::string path = temp_path("gc_beyond_jam") + ".csv";
  write_file(path, "time_s,torque_nm,misalignment_rad,direction_rad,msy_nm,msz_nm\n"
                   "0,1e6,0.1,0,1,2\n0.1,1e6,0.1,0,1,2\n0.2,1e6,0.1,0,1,2\n");
  const ProcessResult run = run_gearcoupling({"validate", "--data", path, "--model", "paper", "--json"});
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.out, "");
  EXPECT_NE(run.err.find("the model refused all 3 samples read (first: operating_point.misalignment_rad"),
            std::string::npos) << run.err;
}

// protobuf's JSON mapping writes 64-bit integers as strings; the counts are 32-bit now.
TEST(RecordingInputCli, CountsInTheJsonAreNumbers) {
  const ProcessResult run = run_gearcoupling({"validate", "--data", kSweep, "--model", "paper", "--json"});
  ASSERT_EQ(run.exit_code, 0) << run.err;
  EXPECT_TRUE(std::regex_search(run.out, std::regex(R"("recording_rows": 1000,)"))) << run.out.substr(0, 300);
  EXPECT_TRUE(std::regex_search(run.out, std::regex(R"("compared_samples": 1000,)")));
  EXPECT_TRUE(std::regex_search(run.out, std::regex(R"("count": [0-9]+,)")));
  EXPECT_FALSE(std::regex_search(run.out, std::regex(R"re("(count|recording_rows|compared_samples|rejected_samples|excluded_rows|line)": ")re")));
}

// Chart.js missing makes --html fail after the run: the target stays as it was.
TEST(RecordingInputCli, AFailedHtmlLeavesNoFileAndAnOldOneUntouched) {
  const std::string html = temp_path("gc_failed_report") + ".html";
  ::setenv("GEARCOUPLING_CHART_JS", "/nonexistent/chart.min.js", 1);
  const ProcessResult fresh = run_gearcoupling({"validate", "--data", kSweep, "--model", "paper", "--html", html});
  write_file(html, "an older report");
  const ProcessResult over = run_gearcoupling({"validate", "--data", kSweep, "--model", "paper", "--html", html});
  ::unsetenv("GEARCOUPLING_CHART_JS");
  EXPECT_NE(fresh.exit_code, 0);
  EXPECT_NE(fresh.err.find("cannot read Chart.js"), std::string::npos) << fresh.err;
  EXPECT_NE(over.exit_code, 0);
  EXPECT_EQ(read_file(html), "an older report");
  const std::filesystem::path dir = std::filesystem::path(html).parent_path();
  for (const auto& entry : std::filesystem::directory_iterator(dir)) {
    EXPECT_FALSE(entry.path().filename().string().starts_with(std::filesystem::path(html).filename().string() + "."))
        << "temporary file left: " << entry.path();
  }
  // And with Chart.js found, the report is written whole.
  const ProcessResult good = run_gearcoupling({"validate", "--data", kSweep, "--model", "paper", "--html", html});
  EXPECT_EQ(good.exit_code, 0) << good.err;
  EXPECT_NE(read_file(html).find("</html>"), std::string::npos);
}

}  // namespace
}  // namespace gc::cli::testing
