// The command line as a whole, run as the user runs it: --version, "--flag=value" on every
// subcommand, aliases, flags a subcommand refuses with a reason, and the bash completion.
#include <array>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "run_process.h"

namespace gc::cli::testing {
namespace {

TEST(CliVersion, PrintsTheProjectVersion) {
  const ProcessResult run = run_gearcoupling({"--version"});
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_EQ(run.out, "gearcoupling " GC_VERSION "\n");
}

TEST(CliFlags, EqualsFormAndAliasesGiveTheSameResult) {
  const ProcessResult spaced = run_gearcoupling(
      {"moments", "--json", "--torque-nm", "1.5e6", "--misalignment-deg", "0.4", "--mu", "0.1"});
  ASSERT_EQ(spaced.exit_code, 0) << spaced.err;
  const ProcessResult equals = run_gearcoupling(
      {"moments", "--json", "--torque-nm=1.5e6", "--misalignment-deg=0.4", "--mu=0.1"});
  EXPECT_EQ(equals.out, spaced.out) << equals.err;
  const ProcessResult alias = run_gearcoupling(
      {"moments", "--json", "--torque", "1.5e6", "--misalignment-deg", "0.4", "--mu", "0.1"});
  EXPECT_EQ(alias.out, spaced.out) << alias.err;
  const ProcessResult friction = run_gearcoupling(
      {"friction", "--json", "--torque=1.5e6", "--misalignment-deg=0.4", "--msy=-5e4",
       "--msz-nm=1.2e5"});
  EXPECT_EQ(friction.exit_code, 0) << friction.err;
}

// A switch takes no value: "--json=3" or "--json=false" is an error naming the flag, not a
// silent --json.
TEST(CliFlags, SwitchesRefuseAValue) {
  for (const char* given : {"--json=3", "--json=false"}) {
    const ProcessResult run = run_gearcoupling({"jam-angle", given});
    EXPECT_EQ(run.exit_code, 2) << given;
    EXPECT_EQ(run.out, "") << given;
    EXPECT_NE(run.err.find("json"), std::string::npos) << run.err;
  }
  EXPECT_EQ(run_gearcoupling({"jam-angle", "--json"}).exit_code, 0);
}

TEST(CliFlags, CatalogueHasOneSpelling) {
  EXPECT_EQ(run_gearcoupling({"jam-angle", "--catalogue", GC_BUNDLED_CATALOG_DIR}).exit_code, 0);
  const ProcessResult old = run_gearcoupling({"jam-angle", "--catalog", GC_BUNDLED_CATALOG_DIR});
  EXPECT_EQ(old.exit_code, 2);
  EXPECT_NE(old.err.find("unknown flag --catalog"), std::string::npos) << old.err;
}

// One bound for every program (protocol/domain_id.h): 230, where the loopback configuration's
// ports still fit.
TEST(CliFlags, DomainIdsStopAt230) {
  const ProcessResult over =
      run_gearcoupling({"jam-angle", "--remote", "--domain", "231", "--timeout-s", "0.1"});
  EXPECT_EQ(over.exit_code, 2);
  EXPECT_NE(over.err.find("--domain"), std::string::npos) << over.err;
  EXPECT_NE(over.err.find("230"), std::string::npos) << over.err;
  const ProcessResult help = run_gearcoupling({"status", "--help"});
  EXPECT_NE(help.out.find("0..230"), std::string::npos) << help.out;
}

struct RefusedCase {
  std::vector<std::string> args;
  std::string expected;
};

class CliRefusedFlag : public ::testing::TestWithParam<RefusedCase> {};

// A flag a subcommand cannot honour is an error naming it, never ignored.
TEST_P(CliRefusedFlag, ExitsTwoNamingTheFlag) {
  const ProcessResult run = run_gearcoupling(GetParam().args);
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_TRUE(run.out.empty()) << run.out;
  EXPECT_NE(run.err.find(GetParam().expected), std::string::npos) << run.err;
  EXPECT_EQ(run.err.find('\n'), run.err.size() - 1) << run.err;
}

const std::string kRecording = GC_SOURCE_DIR "/data/recordings/hidden_eccentricity_torque_ramp.csv";

INSTANTIATE_TEST_SUITE_P(
    Subcommands, CliRefusedFlag,
    ::testing::Values(
        RefusedCase{{"validate", "--data", kRecording, "--model", "paper", "--remote"},
                    "validate: error: --remote: not taken by validate: it computes in process"},
        RefusedCase{{"diagnose", "--data", kRecording, "--model", "paper", "--domain=3"},
                    "diagnose: error: --domain: not taken by diagnose"},
        RefusedCase{{"validate", "--data", kRecording, "--model", "paper", "--coupling",
                     "nrel_downwind"},
                    "--coupling: not taken by validate"},
        RefusedCase{{"synth", "--model", "paper", "--timeout", "5"},
                    "--timeout-s: not taken by synth"},
        RefusedCase{{"synth", "--model", "paper", "--json"},
                    "synth: error: --json: synth writes the recording as CSV"},
        RefusedCase{{"batch", "--in", "-", "--json"},
                    "batch: error: --json: batch writes CSV"}));

TEST(CliHelpText, LeavesOutRefusedFlags) {
  const ProcessResult batch = run_gearcoupling({"batch", "--help"});
  EXPECT_EQ(batch.exit_code, 0);
  EXPECT_EQ(batch.out.find("--json"), std::string::npos) << batch.out;
  const ProcessResult synth = run_gearcoupling({"synth", "--help"});
  EXPECT_EQ(synth.out.find("--json"), std::string::npos) << synth.out;
  EXPECT_EQ(synth.out.find("--remote"), std::string::npos) << synth.out;
  const ProcessResult validate = run_gearcoupling({"validate", "--help"});
  EXPECT_NE(validate.out.find("--json"), std::string::npos) << validate.out;
  EXPECT_EQ(validate.out.find("--coupling"), std::string::npos) << validate.out;
}

// What bash completes after sourcing the installed script, for the words typed so far.
std::string complete(const std::string& words, int current) {
  const std::string command =
      "bash -c 'source \"" GC_BASH_COMPLETION_PATH "\" && COMP_WORDS=(" + words +
      ") && COMP_CWORD=" + std::to_string(current) +
      " && _gearcoupling && printf \"%s \" \"${COMPREPLY[@]}\"'";
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> pipe(popen(command.c_str(), "r"), pclose);
  std::string out;
  std::array<char, 4096> buffer{};
  while (std::fgets(buffer.data(), buffer.size(), pipe.get()) != nullptr) out += buffer.data();
  return out;
}

TEST(CliBashCompletion, CompletesSubcommandsAndTheirFlags) {
  EXPECT_EQ(complete("gearcoupling val", 1), "validate ");
  EXPECT_EQ(complete("gearcoupling ja", 1), "jam-angle ");
  EXPECT_EQ(complete("gearcoupling contact --tor", 2), "--torque-nm ");
  EXPECT_EQ(complete("gearcoupling batch --j", 2), "--jobs ");
  const std::string validate = complete("gearcoupling validate --", 2);
  EXPECT_NE(validate.find("--reference-torque-nm "), std::string::npos) << validate;
  EXPECT_EQ(validate.find("--remote"), std::string::npos) << validate;  // refused there
  EXPECT_NE(complete("gearcoupling diagnose --data " GC_SOURCE_DIR "/data/recordings/hidden_ecc", 3)
                .find("hidden_eccentricity_torque_ramp.csv"),
            std::string::npos);
}

// Issue 39: after --coupling and --model the bundled names, which the program lists when asked
// (so $GEARCOUPLING_CATALOG and $GEARCOUPLING_MODELS count), besides files.
TEST(CliBashCompletion, OffersTheBundledCouplingAndModelNames) {
  const std::string program = GC_GEARCOUPLING_PATH;
  EXPECT_EQ(complete(program + " jam-angle --coupling nrel_", 3), "nrel_downwind nrel_upwind ");
  EXPECT_EQ(complete(program + " validate --model pap", 3), "paper paper_downwind ");
  EXPECT_EQ(complete(program + " contact --coupling nrel_d", 3), "nrel_downwind ");
  const ProcessResult models = run_gearcoupling({"--complete-names", "models"});
  EXPECT_EQ(models.exit_code, 0);
  EXPECT_EQ(models.out, "paper\npaper_downwind\n");
  EXPECT_EQ(run_gearcoupling({"--complete-names", "effects"}).exit_code, 2);
}

TEST(CliBashCompletion, IsWhatTheProgramPrints) {
  const ProcessResult run = run_gearcoupling({"--bash-completion"});
  EXPECT_EQ(run.exit_code, 0);
  EXPECT_EQ(run.out, read_file(GC_BASH_COMPLETION_PATH));
}

}  // namespace
}  // namespace gc::cli::testing
