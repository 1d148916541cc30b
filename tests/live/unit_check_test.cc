// Issue 39, item 3: validate's unit check in replay and the monitor. kN·m numbers under _nm
// headers are refused by replay as validate refuses them (exit 2, the same words); forced
// through, the monitor flags the cell with the same finding and the stream's fix, counts the
// batches, explains no region and starts no diagnosis.
#include <chrono>
#include <fstream>

#include "tests/live/live_fixture.h"
#include "tests/live/live_status.h"

namespace gc::test {
namespace {

using cli::testing::read_file;
using cli::testing::run_gearcoupling;
using namespace std::chrono_literals;

/// The bundled torque sweep with its moments divided by 1000: kN·m under msy_nm and msz_nm.
std::string kilonewton_metres_under_nm() {
  std::ifstream in(GC_SOURCE_DIR "/data/recordings/paper_torque_sweep.csv");
  const std::string path = cli::testing::temp_path("knm_under_nm.csv");
  std::ofstream out(path);
  std::string line;
  std::getline(in, line);
  out << line << "\n";   // time_s,torque_nm,misalignment_rad,direction_rad,msy_nm,msz_nm
  while (std::getline(in, line)) {
    double v[6];
    std::sscanf(line.c_str(), "%lf,%lf,%lf,%lf,%lf,%lf", &v[0], &v[1], &v[2], &v[3], &v[4], &v[5]);
    char row[256];
    std::snprintf(row, sizeof row, "%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n", v[0], v[1], v[2], v[3],
                  v[4] / 1000.0, v[5] / 1000.0);
    out << row;
  }
  return path;
}

constexpr const char* kFinding = "unit error: M_sy' measured RMS";

TEST_F(LiveTest, ReplayRefusesAThousandfoldSlipAsValidateDoes) {
  const std::string slipped = kilonewton_metres_under_nm();
  const auto validated = run_gearcoupling({"validate", "--data", slipped, "--model", "paper"});
  ASSERT_EQ(validated.exit_code, 2) << validated.err;
  const auto replayed = run_gearcoupling(on_test_domain(
      {"replay", "--in", slipped, "--test-cell", "slip", "--speed", "100", "--readers", "0"}));
  EXPECT_EQ(replayed.exit_code, 2) << replayed.out << replayed.err;
  EXPECT_EQ(replayed.out, "");   // nothing published
  EXPECT_NE(replayed.err.find("gearcoupling replay: error: recording: " + slipped + ": " + kFinding),
            std::string::npos) << replayed.err;
  // The same finding and fix, word for word, as validate's.
  const std::string said = validated.err.substr(validated.err.find(kFinding));
  EXPECT_NE(replayed.err.find(said.substr(0, said.find('\n'))), std::string::npos)
      << replayed.err << "\n" << validated.err;
}

TEST_F(LiveTest, TheMonitorFlagsAThousandfoldSlipCountsItAndDoesNotDiagnose) {
  auto monitor = start_monitor({"--window-s", "20", "--health-period-s", "0.2", "--stale-s", "60",
                                "--dispose-s", "120", "--diagnose-after-s", "0", "--diagnosis-nice", "0"});
  const auto replayed = run_gearcoupling(on_test_domain(
      {"replay", "--in", kilonewton_metres_under_nm(), "--test-cell", "slip", "--speed", "20",
       "--force-scale"}));
  ASSERT_EQ(replayed.exit_code, 0) << replayed.err;
  const auto health = health_.wait_for(
      "slip", [](const status::HealthView& h) { return h.taken == 1000 && !h.unit_error.empty(); }, 20s);
  ASSERT_TRUE(health.has_value());
  EXPECT_NE(health->unit_error.find(std::string("test cell slip: ") + kFinding), std::string::npos)
      << health->unit_error;
  EXPECT_NE(health->unit_error.find("too small by about 1000"), std::string::npos) << health->unit_error;
  EXPECT_NE(health->unit_error.find("the publisher must send N·m"), std::string::npos) << health->unit_error;
  EXPECT_EQ(health->learning_state, "unit_error") << health->learning;
  EXPECT_EQ(health->worst_region, "");
  EXPECT_GT(health->unit_slip_batches, 0u);
  // A second's worth of healths later: still no diagnosis, no proposal.
  const v1::LiveStatus status = wait_for_status([](const v1::LiveStatus&) { return true; });
  ASSERT_EQ(status.monitors_size(), 1);
  EXPECT_EQ(status.monitors(0).diagnoses_run(), 0u);
  EXPECT_EQ(status.monitors(0).diagnosing(), "");
  EXPECT_EQ(status.proposals_size(), 0);
}

}  // namespace
}  // namespace gc::test
