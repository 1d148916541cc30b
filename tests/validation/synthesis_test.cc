// Synthesis: the model's predictions plus reproducible Gaussian noise.
#include <cmath>

#include <gtest/gtest.h>

#include "diagnosis/synthesis/load_sequence.h"
#include "diagnosis/synthesis/synthesize.h"
#include "test_models.h"

namespace gc {
namespace {

std::vector<MeasurementSample> sweep(const CouplingModel& model, int samples = 500) {
  LoadSequenceOptions o;
  o.samples = samples;
  o.jam_angle_rad = model.geometry().jam_angle().angle_rad;
  return load_sequence(o);
}

TEST(StandardNormal, HasZeroMeanAndUnitVarianceOverManyDraws) {
  const int n = 200000;
  double sum = 0.0, sum_sq = 0.0;
  for (int i = 0; i < n; ++i) {
    const double x = standard_normal(42, i, 0);
    sum += x;
    sum_sq += x * x;
  }
  // Standard errors: 1/sqrt(n) = 0.0022 for the mean, sqrt(2/n) = 0.0032 for the variance.
  EXPECT_NEAR(sum / n, 0.0, 0.01);
  EXPECT_NEAR(sum_sq / n, 1.0, 0.015);
}

TEST(StandardNormal, DependsOnSeedIndexAndStreamOnly) {
  EXPECT_EQ(standard_normal(7, 123, 1), standard_normal(7, 123, 1));
  EXPECT_NE(standard_normal(7, 123, 1), standard_normal(8, 123, 1));
  EXPECT_NE(standard_normal(7, 123, 1), standard_normal(7, 124, 1));
  EXPECT_NE(standard_normal(7, 123, 1), standard_normal(7, 123, 0));
}

TEST(Synthesize, WithoutNoiseReproducesTheModelExactly) {
  const codec::ModelFile paper = testing::bundled_model("paper");
  const auto inputs = sweep(paper.model);
  const SynthesizedRecording recording = synthesize(paper.model, inputs, {0.0, 1});
  ASSERT_EQ(recording.samples.size(), inputs.size());
  for (const RecordedSample& s : recording.samples) {
    const SensorMoments m = paper.model.predict(s.input).moments;
    EXPECT_EQ(s.measured.y_nm, m.y_nm);
    EXPECT_EQ(s.measured.z_nm, m.z_nm);
  }
}

TEST(Synthesize, SameSeedSameNumbersOtherSeedOtherNoise) {
  const codec::ModelFile paper = testing::bundled_model("paper");
  const auto inputs = sweep(paper.model, 200);
  const auto a = synthesize(paper.model, inputs, {5000.0, 3});
  const auto b = synthesize(paper.model, inputs, {5000.0, 3});
  const auto c = synthesize(paper.model, inputs, {5000.0, 4});
  int differing = 0;
  for (std::size_t i = 0; i < a.samples.size(); ++i) {
    EXPECT_EQ(a.samples[i].measured.y_nm, b.samples[i].measured.y_nm);
    EXPECT_EQ(a.samples[i].measured.z_nm, b.samples[i].measured.z_nm);
    differing += a.samples[i].measured.y_nm != c.samples[i].measured.y_nm;
  }
  EXPECT_EQ(differing, 200);
}

TEST(Synthesize, ListsInputsTheModelRefusesInsteadOfDroppingThem) {
  const codec::ModelFile paper = testing::bundled_model("paper");
  auto inputs = sweep(paper.model, 10);
  inputs[4].misalignment_rad = 2.0 * paper.model.geometry().jam_angle().angle_rad;
  const auto recording = synthesize(paper.model, inputs, {0.0, 1});
  EXPECT_EQ(recording.samples.size(), 9u);
  ASSERT_EQ(recording.rejected.size(), 1u);
  EXPECT_EQ(recording.rejected[0].index, 4u);
  EXPECT_FALSE(recording.rejected[0].reason.empty());
}

}  // namespace
}  // namespace gc
