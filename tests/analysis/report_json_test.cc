// The report's JSON written beside protobuf's printer (analysis/report_json.h): the same text to
// the byte, whatever the numbers, a refused prediction or a model without points.
#include <cmath>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "analysis/report_json.h"
#include "codec/result_json.h"

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
  report.mutable_result()->set_recording("points \"points\": [] here");
  report.mutable_result()->add_warnings("\"points\": []");
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

TEST(ReportJson, LeavesANonFiniteNumberToProtobuf) {
  v1::ValidationReport report = report_with_points();
  report.mutable_plot_points(0)->mutable_points(3)->set_model_msy_nm(std::numeric_limits<double>::quiet_NaN());
  report.mutable_plot_points(2)->mutable_points(0)->set_torque_nm(-std::numeric_limits<double>::infinity());
  EXPECT_EQ(report_json(report), codec::to_json(report));
}

}  // namespace
}  // namespace gc::analysis
