// Two models on one recording (issue 5's before/after): one pass, same bins, side by side in the
// terminal summary and the HTML report.
#include <cstdio>

#include <gtest/gtest.h>

#include "analysis/validation_report_html.h"
#include "analysis/validation_run.h"
#include "analysis/validation_summary.h"
#include "analysis/validation_messages.h"
#include "test_models.h"

namespace gc::analysis {
namespace {

TEST(BeforeAfter, TheModelWithTheHiddenEffectFallsToTheNoiseSideBySide) {
  const codec::ModelFile before = gc::testing::bundled_model("paper");
  const codec::ModelFile after = codec::load_model_description(
      std::string(GC_BUNDLED_RECORDINGS_DIR) + "/hidden_eccentricity.truth.textproto",
      GC_BUNDLED_CATALOG_DIR);
  BinningOptions binning;
  binning.jam_angle_rad = before.model.geometry().jam_angle().angle_rad;
  std::vector<ModelRun> runs;
  runs.push_back({"before", &before.model, ValidationAccumulator(binning), PointSampler(500)});
  runs.push_back({"after", &after.model, ValidationAccumulator(binning), PointSampler(500)});
  const RecordingSummary recording = run_validation(
      std::string(GC_BUNDLED_RECORDINGS_DIR) + "/hidden_eccentricity_torque_ramp.csv", runs,
      {2, 256});
  EXPECT_EQ(recording.rows_read, 1000u);

  // The truth model leaves the 2 kN·m noise of make_recordings.sh; the paper's model more.
  const double before_rmse = runs[0].validation.overall().y.metrics().rmse_nm;
  const double after_rmse = runs[1].validation.overall().y.metrics().rmse_nm;
  EXPECT_GT(before_rmse, 2.0 * after_rmse);
  EXPECT_NEAR(after_rmse, 2000.0, 200.0);
  // Same bins, so regions line up.
  EXPECT_EQ(runs[0].validation.binning(BinDimension::time).bins().size(),
            runs[1].validation.binning(BinDimension::time).bins().size());
  // Same plotted samples.
  ASSERT_EQ(runs[0].points.points().size(), runs[1].points.points().size());
  EXPECT_EQ(runs[0].points.points().back().recorded.input.time_s,
            runs[1].points.points().back().recorded.input.time_s);

  gearcoupling::v1::ValidationReport report;
  for (const ModelRun& run : runs) {
    *report.mutable_result()->add_models() = codec::to_message(run.name, run.validation);
    *report.add_plot_points() = codec::to_message(run.name, run.points.points());
  }
  char* text = nullptr;
  std::size_t size = 0;
  std::FILE* out = open_memstream(&text, &size);
  print_validation_summary(report.result(), out);
  std::fclose(out);
  const std::string summary(text, size);
  std::free(text);
  EXPECT_NE(summary.find("before  M_sy'"), std::string::npos) << summary;
  EXPECT_NE(summary.find("after   M_sy'"), std::string::npos) << summary;
  const std::string html = validation_report_html(report);
  EXPECT_NE(html.find("\"model\": \"after\""), std::string::npos);
}

}  // namespace
}  // namespace gc::analysis
