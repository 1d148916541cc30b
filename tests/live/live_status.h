// What the learning and robustness tests read of the monitors, as an operator does: the
// `gearcoupling proposals --json` and `status --json` records (idl/live_status.proto).
#pragma once

#include <google/protobuf/util/json_util.h>

#include <chrono>
#include <functional>
#include <optional>
#include <string>

#include "idl/live_status.pb.h"
#include "tests/live/live_fixture.h"

namespace gc::test {

namespace v1 = ::gearcoupling::v1;

/// The first line of `text` parsed as `T` (protobuf's JSON mapping); fails the test otherwise.
template <typename T>
T parse_json_line(const std::string& text) {
  T message;
  const std::string line = text.substr(0, text.find('\n'));
  const auto status = google::protobuf::util::JsonStringToMessage(line, &message);
  EXPECT_TRUE(status.ok()) << status.ToString() << "\n" << text;
  return message;
}

/// `proposals --json` for `cell` until `ready` holds for its proposal or `timeout` passes.
inline std::optional<v1::ProposalRecord> wait_for_proposal(
    const std::string& cell, const std::function<bool(const v1::ProposalRecord&)>& ready,
    std::chrono::seconds timeout) {
  const auto until = std::chrono::steady_clock::now() + timeout;
  std::optional<v1::ProposalRecord> latest;
  do {
    const auto listed = cli::testing::run_gearcoupling(on_test_domain(
        {"proposals", "--test-cell", cell, "--json", "--discovery-s", "0.5"}));
    EXPECT_EQ(listed.exit_code, 0) << listed.err;
    const auto list = parse_json_line<v1::ProposalList>(listed.out);
    latest.reset();
    for (const auto& p : list.proposals()) {
      if (p.test_cell() == cell) latest = p;
    }
    if (latest && ready(*latest)) return latest;
  } while (std::chrono::steady_clock::now() < until);
  return latest;
}

/// The monitor's status from `status --json` (one monitor on the test's domain), after
/// `ready` holds for it or `timeout`.
inline v1::LiveStatus wait_for_status(const std::function<bool(const v1::LiveStatus&)>& ready,
                                      std::chrono::seconds timeout = std::chrono::seconds(30)) {
  v1::LiveStatus status;
  const auto until = std::chrono::steady_clock::now() + timeout;
  do {
    const auto shown = cli::testing::run_gearcoupling(
        on_test_domain({"status", "--json", "--discovery-s", "0.5"}));
    EXPECT_EQ(shown.exit_code, 0) << shown.err;
    status = parse_json_line<v1::LiveStatus>(shown.out);
    if (status.monitors_size() == 1 && ready(status)) break;
  } while (std::chrono::steady_clock::now() < until);
  return status;
}

}  // namespace gc::test
