// /metrics of the learning loop (clients/status/learning_metrics.h): per monitor, the proposals,
// diagnoses and swaps it counted and the test cells and foreign samples it refused, each on its
// own line, checked by `promtool check metrics` too (Debian prometheus).
#include "clients/status/learning_metrics.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

namespace gc::status {
namespace {

gearcoupling::v1::MonitorRecord monitor() {
  gearcoupling::v1::MonitorRecord m;
  m.set_monitor_id("00000000000000ab");
  m.set_proposals_published(3);
  m.set_proposals_withdrawn(1);
  m.set_diagnoses_run(5);
  m.set_swaps(2);
  m.set_refused_cell_batches(7);
  m.set_refused_foreign(11);
  (*m.mutable_refusals())["swap_bad_model"] = 4;
  (*m.mutable_refusals())["batch_bad_name"] = 3000;
  return m;
}

bool has_line(const std::string& text, const std::string& line) {
  return ("\n" + text).find("\n" + line + "\n") != std::string::npos;
}

TEST(LearningMetrics, EachCounterOnItsOwnLinePerMonitor) {
  const std::string text = learning_metrics_text({monitor()});
  EXPECT_TRUE(has_line(text, "# TYPE gearcoupling_monitor_proposals_total counter"));
  EXPECT_TRUE(has_line(text, "gearcoupling_monitor_proposals_total{monitor=\"00000000000000ab\"} 3"));
  EXPECT_TRUE(has_line(text, "gearcoupling_monitor_proposals_withdrawn_total{monitor=\"00000000000000ab\"} 1"));
  EXPECT_TRUE(has_line(text, "gearcoupling_monitor_diagnoses_total{monitor=\"00000000000000ab\"} 5"));
  EXPECT_TRUE(has_line(text, "gearcoupling_monitor_swaps_total{monitor=\"00000000000000ab\"} 2"));
  EXPECT_TRUE(has_line(text, "gearcoupling_monitor_cell_batches_refused_total{monitor=\"00000000000000ab\"} 7"));
  EXPECT_TRUE(has_line(text, "gearcoupling_monitor_foreign_refused_total{monitor=\"00000000000000ab\"} 11"));
  // Issue 38: every refusal by kind, kinds in order.
  const std::string bad_name =
      "gearcoupling_monitor_refusals_total{monitor=\"00000000000000ab\",kind=\"batch_bad_name\"} 3000";
  const std::string bad_model =
      "gearcoupling_monitor_refusals_total{monitor=\"00000000000000ab\",kind=\"swap_bad_model\"} 4";
  EXPECT_TRUE(has_line(text, bad_name)) << text;
  EXPECT_TRUE(has_line(text, bad_model)) << text;
  EXPECT_LT(text.find(bad_name), text.find(bad_model));
}

TEST(LearningMetrics, NothingWithoutAMonitor) { EXPECT_EQ(learning_metrics_text({}), ""); }

TEST(LearningMetrics, PromtoolAcceptsThem) {
  if (std::system("command -v promtool > /dev/null 2>&1") != 0) {
    GTEST_SKIP() << "promtool is absent (Debian package prometheus, deploy/install-deps.sh)";
  }
  const std::string path = ::testing::TempDir() + "gearcoupling_learning_metrics.txt";
  std::ofstream(path) << learning_metrics_text({monitor()});
  FILE* pipe = popen(("promtool check metrics < " + path + " 2>&1").c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  std::string output;
  char buffer[512];
  while (std::fgets(buffer, sizeof buffer, pipe) != nullptr) output += buffer;
  const int status = pclose(pipe);
  std::remove(path.c_str());
  EXPECT_EQ(status, 0) << output;
  EXPECT_EQ(output, "");
}

}  // namespace
}  // namespace gc::status
