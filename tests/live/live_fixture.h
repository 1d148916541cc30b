// What the live tests share: the test's DDS domain on loopback (tests/service/service_process.h),
// a gearcoupling-monitor child, a participant of the test's own, the bundled data.
#pragma once

#include <algorithm>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "clients/status/cell_board.h"
#include "live/live_topics.h"
#include "tests/cli/run_process.h"
#include "tests/service/service_process.h"

namespace gc::test {

inline const std::string kHiddenEccentricity =
    GC_SOURCE_DIR "/data/recordings/hidden_eccentricity_torque_ramp.csv";

/// gearcoupling-monitor on the test's domain with `extra_args`, its log in a temporary file.
inline std::unique_ptr<ChildProcess> start_monitor(const std::vector<std::string>& extra_args,
                                                   std::string* log_path = nullptr) {
  std::vector<std::string> args = {GC_MONITOR_BINARY, "--domain", std::to_string(test_domain())};
  // warn unless the test reads the info lines (the flag is taken once).
  if (std::find(extra_args.begin(), extra_args.end(), "--log-level") == extra_args.end()) {
    args.insert(args.end(), {"--log-level", "warn"});
  }
  args.insert(args.end(), extra_args.begin(), extra_args.end());
  const std::string log = cli::testing::temp_path("monitor_log");
  if (log_path != nullptr) *log_path = log;
  return std::make_unique<ChildProcess>(args, log, std::vector<std::pair<std::string, std::string>>{},
                                        std::string{}, true);
}

/// The `gearcoupling` flags that put a live subcommand on the test's domain.
inline std::vector<std::string> on_test_domain(std::vector<std::string> args) {
  args.push_back("--domain");
  args.push_back(std::to_string(test_domain()));
  return args;
}

class LiveTest : public ::testing::Test {
 protected:
  protocol::Entity participant_ = live::make_participant(test_domain());
  status::CellBoard health_{participant_.get()};
};

}  // namespace gc::test
