// gearcoupling --remote prints exactly what gearcoupling prints in process, for every
// subcommand, in tables and JSON, and for batch with N requests in flight.
#include <csignal>
#include <chrono>

#include <gtest/gtest.h>

#include "client/client.h"
#include "protocol/matching.h"
#include "tests/cli/run_process.h"
#include "tests/service/service_process.h"

namespace gc {
namespace {

using cli::testing::run_gearcoupling;

/// The command's result and how long it took, start of the process to its exit [s].
struct TimedRun {
  cli::testing::ProcessResult result;
  double seconds = 0.0;
};

TimedRun run_timed(const std::vector<std::string>& args) {
  const auto start = std::chrono::steady_clock::now();
  TimedRun run{run_gearcoupling(args)};
  run.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

/// What a command may take beyond its --timeout-s: the process's start and DDS set-up and
/// leaving the domain (0.1-0.3 s here), with room for a loaded host; less than one more
/// timeout, which is what a second request waiting afresh costs.
constexpr double kTimeoutMarginS = 1.2;
constexpr double kTimeoutS = 2.0;

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

// Issue 40: batch --remote sends its rows as batches of cases (512 a request), not a request per
// row, and prints byte for byte what batch prints in process (tolerance: none; the same core
// calls), bad rows included: one that does not parse, a negative torque, a misalignment beyond
// the jam angle; over two catalogue couplings and a coupling file (sent inline).
TEST(RemoteCli, BatchSendsRowsInBatchesAndPrintsWhatItPrintsInProcess) {
  test::ServiceProcess service({"--status-interval-s", "0.1"});
  const std::string in = cli::testing::temp_path("remote_batches_in");
  const std::string file = GC_SOURCE_DIR "/data/couplings/nrel_downwind.textproto";
  std::string csv = "torque_nm,misalignment_deg,direction_deg,mu,coupling\n";
  constexpr int kRows = 5000;
  for (int r = 0; r < kRows; ++r) {
    const char* coupling = r % 3 == 0 ? "nrel_upwind" : r % 3 == 1 ? "nrel_downwind" : file.c_str();
    csv += std::to_string(2.0e5 + 611.0 * r) + "," + std::to_string(0.0001 * (r % 4000)) + "," +
           std::to_string(r % 360) + "," + std::to_string(0.00004 * (r % 5000)) + "," + coupling +
           "\n";
    if (r == 1500) csv += "abc,0.1,0,0.1,nrel_upwind\n";
    if (r == 2500) csv += "-5,0.1,0,0.1,nrel_upwind\n";
    if (r == 3500) csv += "1.5e6,5,0,0.1,nrel_downwind\n";
  }
  cli::testing::write_file(in, csv);
  const auto local = run_gearcoupling({"batch", "--in", in, "-j", "2"});
  const auto over_dds = run_gearcoupling(remote({"batch", "--in", in, "-j", "2"}));
  EXPECT_EQ(local.exit_code, 1);  // the three bad rows
  EXPECT_EQ(over_dds.exit_code, local.exit_code) << over_dds.err;
  EXPECT_EQ(over_dds.out, local.out);
  EXPECT_EQ(over_dds.err, local.err);
  EXPECT_NE(local.err.find("3 of 5003 rows failed"), std::string::npos) << local.err;

  // The service saw a few batches (5003 rows: 2502 and 2501 per thread, 5 batches of at most 512
  // each) and no single request.
  client::Client client({.domain = test::test_domain(), .timeout = std::chrono::seconds(10)});
  ASSERT_TRUE(client.wait_for_service(protocol::Calculation::kBatch, std::chrono::seconds(10)));
  std::uint64_t batches = 0;
  ASSERT_TRUE(protocol::wait_until(
      [&] {
        for (const client::InstanceInfo& instance : client.instances()) {
          for (const client::CalculationStatus& c : instance.calculations) {
            if (c.calculation == "batch") batches = c.served + c.refused + c.failed;
            if (c.calculation != "batch") EXPECT_FALSE(c.called()) << c.calculation;
          }
        }
        return batches > 0;
      },
      std::chrono::steady_clock::now() + std::chrono::seconds(5)));
  EXPECT_EQ(batches, 10u);
}

// Issue 24: `moments --remote --timeout-s 2` with no service took 4.0 s: its two requests each
// waited 2 s for an instance. The timeout is the command's deadline.
TEST(RemoteCli, TimeoutBoundsTheWholeCommandWhenNoServiceRuns) {
  for (const std::vector<std::string>& command :
       {std::vector<std::string>{"moments", "--torque-nm", "1.5e6", "--misalignment-deg", "0.3",
                                 "--mu", "0.1"},
        std::vector<std::string>{"jam-angle"}}) {
    std::vector<std::string> args = remote(command);
    args.insert(args.end(), {"--timeout-s", "2"});
    const TimedRun run = run_timed(args);
    SCOPED_TRACE(command.front());
    EXPECT_EQ(run.result.exit_code, 1) << run.result.err;
    EXPECT_NE(run.result.err.find("no gearcoupling-service instance ready"), std::string::npos)
        << run.result.err;
    EXPECT_NE(run.result.err.find("within 2000 ms"), std::string::npos) << run.result.err;
    // The configuration used (service_process.cc sets CYCLONEDDS_URI) and how to start a service.
    EXPECT_NE(run.result.err.find("DDS configuration: CYCLONEDDS_URI=file://"), std::string::npos)
        << run.result.err;
    EXPECT_NE(run.result.err.find("gearcoupling-service --domain"), std::string::npos)
        << run.result.err;
    EXPECT_GE(run.seconds, kTimeoutS - 0.05);
    EXPECT_LT(run.seconds, kTimeoutS + kTimeoutMarginS);
  }
}

// A service that was found and then stops answering (SIGSTOP: alive to the OS, silent on DDS):
// batch -j 1 sends its rows one after the other, two requests a row; every row after the
// deadline fails at once instead of waiting a timeout of its own (before: 3 rows x 2 s).
TEST(RemoteCli, TimeoutBoundsAWholeBatchOnAStoppedService) {
  test::ServiceProcess service;
  // Found and answering first, so the stop comes after discovery.
  ASSERT_EQ(run_gearcoupling(remote({"jam-angle"})).exit_code, 0);
  const std::string in = cli::testing::temp_path("stopped_batch_in");
  cli::testing::write_file(in, "torque_nm,misalignment_deg,direction_deg,mu\n"
                               "1.5e6,0.3,0,0.1\n2.0e6,0.2,0,0.1\n2.5e6,0.1,0,0.1\n");
  service.signal(SIGSTOP);
  const TimedRun run = run_timed(remote({"batch", "--in", in, "-j", "1", "--timeout-s", "2"}));
  service.signal(SIGCONT);
  EXPECT_EQ(run.result.exit_code, 1) << run.result.err;
  EXPECT_NE(run.result.err.find("line 2:"), std::string::npos) << run.result.err;
  EXPECT_NE(run.result.err.find("line 4:"), std::string::npos) << run.result.err;
  EXPECT_LT(run.seconds, kTimeoutS + kTimeoutMarginS) << run.result.err;
}

}  // namespace
}  // namespace gc
