// /metrics: the status and the test cells in Prometheus text, checked line by line and by
// Prometheus's own `promtool check metrics` (Debian prometheus).
#include "clients/status/status_metrics.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

#include "clients/status/prometheus_text.h"

namespace gc::status {
namespace {

InstanceView instance(std::uint64_t id, std::string host, Liveness liveness) {
  InstanceView view;
  view.info.id = id;
  view.info.host = std::move(host);
  view.info.pid = 42;
  view.info.accepting = true;
  view.info.uptime_s = 12.5;
  // served, failed, p50, p99, refused, sum of service times; restoring_torque never called.
  view.info.calculations = {{"jam_angle", 7, 1, 0.00025, 0.0015, 2, 0.0125},
                            {"tooth_contact", 3, 0, 0.002, 0.004, 0, 0.0075},
                            {"restoring_torque", 0, 0, 0.0, 0.0, 0, 0.0}};
  view.liveness = liveness;
  return view;
}

v1::TestCellRecord test_cell(std::string name) {
  v1::TestCellRecord cell;
  cell.set_test_cell(std::move(name));
  cell.set_state("alive");
  cell.mutable_counts()->set_taken(40000);
  cell.mutable_counts()->set_evaluated(39990);
  cell.mutable_counts()->set_refused_by_model(10);
  cell.mutable_model()->set_model_name("paper");
  cell.mutable_model()->mutable_msy()->set_rmse_nm(1500.0);
  cell.mutable_model()->mutable_msy()->set_bias_nm(-1200.0);
  cell.mutable_model()->mutable_msy()->set_noise_nm(900.0);
  cell.mutable_model()->mutable_msz()->set_rmse_nm(800.0);
  cell.set_model_health("systematic");
  return cell;
}

std::string metrics() {
  return metrics_text({instance(0xabc, "cell-host", Liveness::kAlive),
                       instance(0xdef, "odd \"host\"\\\n", Liveness::kStale)},
                      {test_cell("dyno-5mw")});
}

bool has_line(const std::string& text, const std::string& line) {
  return text.find("\n" + line + "\n") != std::string::npos;
}

TEST(Metrics, CountersPerInstanceAndCalculationEndInTotal) {
  const std::string text = metrics();
  EXPECT_TRUE(has_line(text, "# TYPE gearcoupling_requests_served_total counter"));
  EXPECT_TRUE(has_line(text, "gearcoupling_requests_served_total{service_instance=\"0000000000000abc\","
                             "host=\"cell-host\",calculation=\"jam_angle\"} 7"));
  EXPECT_TRUE(has_line(text, "gearcoupling_requests_failed_total{service_instance=\"0000000000000abc\","
                             "host=\"cell-host\",calculation=\"jam_angle\"} 1"));
}

TEST(Metrics, LatencyIsASummaryWithQuantileLabelsInSeconds) {
  const std::string text = metrics();
  EXPECT_TRUE(has_line(text, "# TYPE gearcoupling_service_time_seconds summary"));
  EXPECT_TRUE(has_line(text, "gearcoupling_service_time_seconds{service_instance=\"0000000000000abc\","
                             "host=\"cell-host\",calculation=\"tooth_contact\",quantile=\"0.99\"} 0.004"));
}

TEST(Metrics, AStaleInstanceIsDownAndLabelValuesAreEscaped) {
  const std::string text = metrics();
  EXPECT_TRUE(has_line(text, "gearcoupling_instance_up{service_instance=\"0000000000000def\","
                             "host=\"odd \\\"host\\\"\\\\\\n\"} 0"));
}

TEST(Metrics, TestCellsHaveSampleCountersAndRmseWithNoisePerChannel) {
  const std::string text = metrics();
  EXPECT_TRUE(has_line(text, "gearcoupling_cell_samples_taken_total{test_cell=\"dyno-5mw\"} 40000"));
  EXPECT_TRUE(has_line(text, "gearcoupling_cell_samples_refused_total{test_cell=\"dyno-5mw\","
                             "reason=\"by_model\"} 10"));
  EXPECT_TRUE(has_line(text, "gearcoupling_cell_rmse_newton_metres{test_cell=\"dyno-5mw\","
                             "channel=\"msy\"} 1500"));
  EXPECT_TRUE(has_line(text, "gearcoupling_cell_noise_newton_metres{test_cell=\"dyno-5mw\","
                             "channel=\"msy\"} 900"));
}

TEST(Metrics, NoLabelIsNamedInstanceWhichPrometheusSetsToTheTarget) {
  const std::string text = metrics();
  EXPECT_EQ(text.find("{instance="), std::string::npos);
  EXPECT_EQ(text.find(",instance="), std::string::npos);
}

TEST(Metrics, TheSummaryHasSumAndCountAndNanQuantilesWhenNeverCalled) {
  const std::string text = metrics();
  const std::string labels = "{service_instance=\"0000000000000abc\",host=\"cell-host\",";
  // _count: every answered request, refused ones included (7 + 1 + 2).
  EXPECT_TRUE(has_line(text, "gearcoupling_service_time_seconds_count" + labels +
                                 "calculation=\"jam_angle\"} 10"));
  EXPECT_TRUE(has_line(text, "gearcoupling_service_time_seconds_sum" + labels +
                                 "calculation=\"jam_angle\"} 0.0125"));
  EXPECT_TRUE(has_line(text, "gearcoupling_service_time_seconds" + labels +
                                 "calculation=\"restoring_torque\",quantile=\"0.99\"} NaN"));
  EXPECT_TRUE(has_line(text, "gearcoupling_service_time_seconds_count" + labels +
                                 "calculation=\"restoring_torque\"} 0"));
}

TEST(Metrics, RefusedRequestsAreCountedApartFromFailedOnes) {
  const std::string text = metrics();
  EXPECT_TRUE(has_line(text, "gearcoupling_requests_refused_total{service_instance=\"0000000000000abc\","
                             "host=\"cell-host\",calculation=\"jam_angle\"} 2"));
  EXPECT_TRUE(has_line(text, "gearcoupling_requests_failed_total{service_instance=\"0000000000000abc\","
                             "host=\"cell-host\",calculation=\"jam_angle\"} 1"));
}

TEST(Metrics, TestCellsHaveTheirModelBiasAndHealth) {
  const std::string text = metrics();
  EXPECT_TRUE(has_line(text, "# TYPE gearcoupling_cell_model_info gauge"));
  EXPECT_TRUE(has_line(text, "gearcoupling_cell_model_info{test_cell=\"dyno-5mw\",model=\"paper\"} 1"));
  EXPECT_TRUE(has_line(text, "gearcoupling_cell_bias_newton_metres{test_cell=\"dyno-5mw\","
                             "channel=\"msy\"} -1200"));
  EXPECT_TRUE(has_line(text, "gearcoupling_cell_model_health{test_cell=\"dyno-5mw\","
                             "health=\"systematic\"} 1"));
  EXPECT_TRUE(has_line(text, "gearcoupling_cell_model_health{test_cell=\"dyno-5mw\","
                             "health=\"far_off\"} 0"));
}

// Issue 39: a gone cell exported its last badge (at_noise_level 1) for as long as it was listed.
TEST(Metrics, AGoneOrStaleCellIsMarkedStaleNotItsLastHealth) {
  for (const std::string state : {"gone", "stale"}) {
    v1::TestCellRecord cell = test_cell("left");
    cell.set_state(state);
    cell.set_model_health("at_noise_level");
    const std::string text = metrics_text({}, {cell});
    EXPECT_TRUE(has_line(text, "gearcoupling_cell_model_health{test_cell=\"left\",health=\"stale\"} 1")) << text;
    EXPECT_TRUE(has_line(text, "gearcoupling_cell_model_health{test_cell=\"left\",health=\"at_noise_level\"} 0")) << text;
  }
  const std::string alive = metrics();
  EXPECT_TRUE(has_line(alive, "gearcoupling_cell_model_health{test_cell=\"dyno-5mw\",health=\"stale\"} 0"));
}

// Issue 39: what the learning loop does for a cell, as a labelled gauge, and what it lacks.
TEST(Metrics, TheLearningStateAndTheSamplesItLacksAreExported) {
  v1::TestCellRecord cell = test_cell("slow");
  cell.set_learning_state("waiting_for_samples");
  cell.set_learning_samples_missing(120);
  cell.set_sample_rate_hz(10.0);
  cell.mutable_counts()->set_unit_slip_batches(3);
  const std::string text = metrics_text({}, {cell});
  EXPECT_TRUE(has_line(text, "gearcoupling_cell_learning_state{test_cell=\"slow\",state=\"waiting_for_samples\"} 1")) << text;
  EXPECT_TRUE(has_line(text, "gearcoupling_cell_learning_samples_missing{test_cell=\"slow\"} 120")) << text;
  EXPECT_TRUE(has_line(text, "gearcoupling_cell_sample_rate_hertz{test_cell=\"slow\"} 10")) << text;
  EXPECT_TRUE(has_line(text, "gearcoupling_cell_unit_slip_batches_total{test_cell=\"slow\"} 3")) << text;
}

TEST(Metrics, PromtoolAcceptsTheText) {
  if (std::system("command -v promtool > /dev/null 2>&1") != 0) {
    GTEST_SKIP() << "promtool is absent (Debian package prometheus, deploy/install-deps.sh)";
  }
  const std::string path = ::testing::TempDir() + "gearcoupling_metrics.txt";
  std::ofstream(path) << metrics();
  const std::string command = "promtool check metrics < " + path + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  ASSERT_NE(pipe, nullptr);
  std::string output;
  char buffer[512];
  while (std::fgets(buffer, sizeof buffer, pipe) != nullptr) output += buffer;
  const int status = pclose(pipe);
  std::remove(path.c_str());
  EXPECT_EQ(status, 0) << output;
  EXPECT_EQ(output, "");  // no lint complaints either
}

}  // namespace
}  // namespace gc::status
