// The dashboard under DDS Security (docs/dashboard.md, "Security"): its query panel asks the
// service under a console identity (a dashboard's and a client's rights) with --client-id-prefix
// (or GC_CLIENT_ID_PREFIX), and under a dashboard identity, which may not ask, it answers 403
// saying why and what to do, while the rest of the dashboard keeps working. Certificates made at test time by make-security.sh.
#include <chrono>
#include <fstream>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include <fmt/format.h>
#include <gtest/gtest.h>

#include "clients/dashboard/query_panel.h"
#include "tests/service/secure_cell.h"
#include "tests/service/secure_cell_test.h"
#include "tests/service/service_process.h"

// After the headers that include Eigen: httplib.h brings <resolv.h>, whose macro _res clashes
// with Eigen's parameter names.
#include <httplib.h>

namespace gc {
namespace {

constexpr int kDashboardDomain = 228;
constexpr const char* kQuery =
    "/api/query?coupling=nrel_upwind&torque_nm=1.5e6&misalignment_deg=0.3&friction_coefficient=0.1";
constexpr const char* kWhy = "may not ask the service";
constexpr const char* kWhatToDo = "--client-id-prefix";

/// An HTTP GET's status (-1 when nothing answered) and body.
struct HttpAnswer {
  int status = -1;
  std::string body;
};

HttpAnswer http_get(int port, const std::string& path) {
  httplib::Client http("127.0.0.1", port);
  http.set_read_timeout(60, 0);
  const auto answer = http.Get(path);
  return answer ? HttpAnswer{answer->status, answer->body} : HttpAnswer{};
}

class SecureDashboard : public test::SecureCellTest {
 protected:
  void SetUp() override {
    make_cell("--console main");
  }
  /// gearcoupling-dashboard under `identity` on a free port, with `args` and `environment`
  /// added; its port once it printed it (0 when it did not within 30 s).
  int start_dashboard(const std::string& identity, std::vector<std::string> args,
                      std::vector<std::pair<std::string, std::string>> environment = {}) {
    const std::string log = cell_->dir() + "/dashboard-" + std::to_string(dashboards_.size()) + ".log";
    args.insert(args.begin(), {GC_DASHBOARD_BINARY, "--domain", std::to_string(test::test_domain()),
                               "--listen", "127.0.0.1:0", "--query-timeout", "30"});
    environment.emplace_back("CYCLONEDDS_URI", cell_->uri(identity));
    dashboards_.push_back(std::make_unique<test::ChildProcess>(args, log, environment, "", true));
    for (int k = 0; k < 300; ++k) {
      std::ifstream in(log);
      for (std::string line; std::getline(in, line);) {
        if (line.rfind("listening on http://127.0.0.1:", 0) == 0) {
          return std::stoi(line.substr(std::string("listening on http://127.0.0.1:").size()));
        }
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    return 0;
  }
  std::unique_ptr<test::ServiceProcess> start_service() const {
    return std::make_unique<test::ServiceProcess>(
        std::vector<std::string>{}, cell_->dir() + "/service.log",
        std::vector<std::pair<std::string, std::string>>{{"CYCLONEDDS_URI", cell_->uri("service-main")}});
  }
  std::vector<std::unique_ptr<test::ChildProcess>> dashboards_;
};

TEST_F(SecureDashboard, UnderAConsoleIdentityItsPrefixFromTheEnvironmentLetsThePanelAsk) {
  const auto service = start_service();
  const int port = start_dashboard(
      "console-main", {},
      {{"GC_CLIENT_ID_PREFIX", fmt::format("{:08x}", cell_->prefix_of("console-main"))}});
  ASSERT_GT(port, 0);
  const HttpAnswer answer = http_get(port, kQuery);
  EXPECT_EQ(answer.status, 200) << answer.body;
  EXPECT_NE(answer.body.find("\"jam_angle\""), std::string::npos) << answer.body;
}

TEST_F(SecureDashboard, UnderAConsoleIdentityWithoutItsPrefixThePanelSaysWhatToDo) {
  const auto service = start_service();
  const int port = start_dashboard("console-main", {"--client-id-prefix", ""});
  ASSERT_GT(port, 0);
  const HttpAnswer answer = http_get(port, kQuery);
  EXPECT_EQ(answer.status, 403) << answer.body;
  EXPECT_NE(answer.body.find(kWhatToDo), std::string::npos) << answer.body;
}

TEST_F(SecureDashboard, UnderADashboardIdentityThePanelSaysWhyAndWhatToDoAndTheRestWorks) {
  const auto service = start_service();
  const int port = start_dashboard("dashboard-main", {});
  ASSERT_GT(port, 0);
  const HttpAnswer answer = http_get(port, kQuery);
  EXPECT_EQ(answer.status, 403) << answer.body;
  EXPECT_NE(answer.body.find(kWhy), std::string::npos) << answer.body;
  EXPECT_NE(answer.body.find(kWhatToDo), std::string::npos) << answer.body;
  EXPECT_EQ(http_get(port, "/api/state").status, 200);
}

TEST_F(SecureDashboard, UnderADashboardIdentityWithAClientsPrefixThePanelStillSaysWhy) {
  // The prefix makes the client probe its reply partition at once: refused, and the dashboard
  // must still come up, its panel answering 403.
  const test::LocalDomain domain(kDashboardDomain, cell_->uri("dashboard-main"));
  dashboard::QueryPanel panel({kDashboardDomain, std::chrono::seconds(5), cell_->client_prefix("a")});
  const dashboard::JsonAnswer answer = panel.answer({{"coupling", "nrel_upwind"},
                                                     {"torque_nm", "1e6"},
                                                     {"misalignment_deg", "0.2"}});
  EXPECT_EQ(answer.status, 403) << answer.body;
  EXPECT_NE(answer.body.find(kWhy), std::string::npos) << answer.body;
}

// Issue 25: applying a monitor's proposal is a model swap, an operator's right. A dashboard
// identity asked to (--operator-cells) does not start, saying why; without the flag it is
// read-only and its apply endpoint answers 403.
TEST_F(SecureDashboard, UnderADashboardIdentityApplyingProposalsIsRefused) {
  const test::ShellResult refused = test::run_shell(
      "CYCLONEDDS_URI='" + cell_->uri("dashboard-main") + "' " GC_DASHBOARD_BINARY " --domain " +
      std::to_string(test::test_domain()) + " --listen 127.0.0.1:0 --operator-cells c --operator tester");
  EXPECT_EQ(refused.exit_code, 1) << refused.output;
  EXPECT_NE(refused.output.find("--operator-cells c: this dashboard's DDS identity may not publish "
                                "model swaps"), std::string::npos) << refused.output;
  const int port = start_dashboard("dashboard-main", {});
  ASSERT_GT(port, 0);
  httplib::Client http("127.0.0.1", port);
  const auto answer = http.Post("/api/apply", httplib::Headers{{"X-Gearcoupling-Apply", "1"}},
                                "test_cell=c&proposal=0123456789abcdef",
                                "application/x-www-form-urlencoded");
  ASSERT_TRUE(answer);
  EXPECT_EQ(answer->status, 403) << answer->body;
  EXPECT_NE(answer->body.find("read-only"), std::string::npos) << answer->body;
}

TEST_F(SecureDashboard, ABadClientIdPrefixIsRefusedNamingTheFlag) {
  const test::ShellResult refused = test::run_shell(
      GC_DASHBOARD_BINARY " --client-id-prefix 12345 --listen 127.0.0.1:0");
  EXPECT_EQ(refused.exit_code, 2);
  EXPECT_NE(refused.output.find("--client-id-prefix \"12345\": allowed 8 hexadecimal digits"),
            std::string::npos) << refused.output;
}

}  // namespace
}  // namespace gc
