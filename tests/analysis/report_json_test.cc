// The report's JSON written beside protobuf's printer (analysis/report_json.h): the same text to
// the byte, whatever the numbers, a refused prediction or a model without points.
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "analysis/model_validation.h"
#include "analysis/report_json.h"
#include "analysis/validation_report_html.h"
#include "codec/result_json.h"
#include "test_models.h"

namespace gc::analysis {
namespace {

namespace v1 = gearcoupling::v1;

void add_point(v1::ValidationReport::ModelPoints& model, double x, int direction, bool predicted) {
  v1::PlotPoint& point = *model.add_points();
  point.set_time_s(x);
  point.set_torque_nm(-x * 1e6);
  point.set_misalignment_rad(x * 1e-3);
  point.set_direction_rad(0.0);
  point.set_loading_direction(direction);
  point.set_msy_nm(0.1 + 0.2);   // needs 17 digits
  point.set_msz_nm(-0.0);
  if (predicted) {
    point.set_model_msy_nm(150000.0);
    point.set_model_msz_nm(x * 1e300);
  }
}

v1::ValidationReport report_with_points() {
  v1::ValidationReport report;
  std::string every_character;
  for (int c = 1; c < 128; ++c) every_character += static_cast<char>(c);
  report.mutable_result()->set_recording(every_character + " N·m, ζ 0.2°");
  report.mutable_result()->add_warnings("\"points\": []");
  report.mutable_result()->add_models()->set_model("no metrics set");
  report.set_colour_scale_max_nm(2000.5);
  v1::ValidationReport::ModelPoints& first = *report.add_plot_points();
  first.set_model("paper");
  std::mt19937 random(3);
  std::uniform_real_distribution<double> value(-10.0, 10.0);
  for (int i = 0; i < 500; ++i) add_point(first, i == 0 ? 0.0 : value(random), i % 3 - 1, i % 7 != 0);
  report.add_plot_points()->set_model("no points");
  v1::ValidationReport::ModelPoints& third = *report.add_plot_points();
  third.set_model("paper + hysteresis");
  for (double x : {1e-05, 2.56, 123456789012345678.0, 5e-324}) add_point(third, x, 1, true);
  return report;
}

TEST(ReportJson, IsProtobufsTextToTheByte) {
  const v1::ValidationReport report = report_with_points();
  EXPECT_EQ(report_json(report), codec::to_json(report));
  EXPECT_EQ(report_json(v1::ValidationReport()), codec::to_json(v1::ValidationReport()));
}

// A real report: metrics, bins, maps, regions and rejections of two models.
TEST(ReportJson, IsProtobufsTextForAValidatedRecording) {
  const codec::ModelFile model = gc::testing::bundled_model("paper");
  const auto validation = validate_model(
      std::string(GC_BUNDLED_RECORDINGS_DIR) + "/hidden_eccentricity_torque_ramp.csv", model,
      "hysteresis=lag_rad=6e-4", 1.5e6, {2, 256});
  const v1::ValidationReport report = validation_report(validation->result, validation->runs);
  ASSERT_EQ(report.plot_points_size(), 2);
  const std::string ours = report_json(report), protobufs = codec::to_json(report);
  EXPECT_TRUE(ours == protobufs);  // not EXPECT_EQ: a difference would print 1 MB
  if (ours != protobufs) {
    std::FILE* a = std::fopen("/tmp/report_json_ours.json", "w");
    std::fputs(ours.c_str(), a);
    std::fclose(a);
    std::FILE* b = std::fopen("/tmp/report_json_protobufs.json", "w");
    std::fputs(protobufs.c_str(), b);
    std::fclose(b);
  }
}

TEST(ReportJson, LeavesANonFiniteNumberToProtobuf) {
  v1::ValidationReport report = report_with_points();
  report.mutable_plot_points(0)->mutable_points(3)->set_model_msy_nm(std::numeric_limits<double>::quiet_NaN());
  report.mutable_plot_points(2)->mutable_points(0)->set_torque_nm(-std::numeric_limits<double>::infinity());
  EXPECT_EQ(report_json(report), codec::to_json(report));
}

}  // namespace
}  // namespace gc::analysis
