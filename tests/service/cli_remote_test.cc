// gearcoupling --remote prints exactly what gearcoupling prints in process, for every
// subcommand, in tables and JSON, and for batch with N requests in flight.
#include <gtest/gtest.h>

#include "tests/cli/run_process.h"
#include "tests/service/service_process.h"

namespace gc {
namespace {

using cli::testing::run_gearcoupling;

std::vector<std::string> remote(std::vector<std::string> args) {
  args.insert(args.end(), {"--remote", "--domain", std::to_string(test::test_domain())});
  return args;
}

void expect_same_output(const std::vector<std::string>& args) {
  std::string joined;
  for (const std::string& arg : args) joined += arg + " ";
  SCOPED_TRACE(joined);
  const auto local = run_gearcoupling(args);
  const auto over_dds = run_gearcoupling(remote(args));
  EXPECT_EQ(over_dds.exit_code, local.exit_code) << over_dds.err;
  EXPECT_EQ(over_dds.out, local.out);
  EXPECT_FALSE(local.out.empty() && local.exit_code == 0);
}

TEST(RemoteCli, EverySubcommandPrintsWhatItPrintsInProcess) {
  test::ServiceProcess service;
  const std::string file = GC_SOURCE_DIR "/data/couplings/nrel_downwind.textproto";
  for (const std::string coupling : {"nrel_upwind", "nrel_downwind"}) {
    for (const std::vector<std::string>& json : {std::vector<std::string>{},
                                                std::vector<std::string>{"--json"}}) {
      auto with = [&](std::vector<std::string> args) {
        args.insert(args.end(), {"--coupling", coupling});
        args.insert(args.end(), json.begin(), json.end());
        return args;
      };
      expect_same_output(with({"jam-angle"}));
      expect_same_output(with({"restoring-torque"}));
      expect_same_output(with({"contact", "--torque-nm", "1.5e6", "--misalignment-deg", "0.5",
                               "--mu", "0.1"}));
      expect_same_output(with({"moments", "--torque-nm", "2.2e6", "--misalignment-deg", "0.3",
                               "--direction-deg", "30", "--mu", "0.12", "--slices", "12"}));
      expect_same_output(with({"friction", "--torque-nm", "1.5e6", "--misalignment-deg", "0.4",
                               "--msy-nm", "5.0e4", "--msz-nm", "8.0e4"}));
    }
  }
  expect_same_output({"jam-angle", "--coupling", file});
  // A bad input fails the same way (exit code 2, nothing on standard output).
  expect_same_output({"moments", "--torque-nm", "-1", "--misalignment-deg", "0.3", "--mu", "0.1"});
}

TEST(RemoteCli, BatchWithRequestsInFlightPrintsWhatItPrintsInProcess) {
  test::ServiceProcess service;
  const std::string in = cli::testing::temp_path("remote_batch_in");
  std::string csv = "torque_nm,misalignment_deg,direction_deg,mu,coupling\n";
  for (int r = 0; r < 400; ++r) {
    csv += std::to_string(2.0e5 + 7.0e3 * r) + "," + std::to_string(0.002 * (r % 300)) + "," +
           std::to_string(r % 360) + ",0.1," + (r % 2 ? "nrel_upwind" : "nrel_downwind") + "\n";
  }
  csv += "-5,0.1,0,0.1,nrel_upwind\n";  // a bad row: reported identically
  cli::testing::write_file(in, csv);
  const auto local = run_gearcoupling({"batch", "--in", in});
  const auto over_dds = run_gearcoupling(remote({"batch", "--in", in, "-j", "8"}));
  EXPECT_EQ(over_dds.exit_code, local.exit_code) << over_dds.err;
  EXPECT_EQ(over_dds.out, local.out);
  EXPECT_EQ(over_dds.err, local.err);
  EXPECT_GT(local.out.size(), 400u * 50u);
}

}  // namespace
}  // namespace gc
