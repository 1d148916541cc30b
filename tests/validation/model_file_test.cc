// Model configuration files: the bundled paper model, errors that name the field and the file,
// and the writer whose output reads back to the same model.
#include <gtest/gtest.h>

#include "codec/model_file.h"
#include "core/model_error.h"
#include "test_models.h"

namespace gc {
namespace {

using testing::bundled_model;

codec::ModelFile parse(const std::string& text) {
  return codec::parse_model_text(text, "bad.textproto", GC_BUNDLED_CATALOG_DIR, ".");
}

// The InvalidInput that parsing `text` raises (fails the test when there is none).
InvalidInput error_of(const std::string& text) {
  try {
    parse(text);
  } catch (const InvalidInput& error) {
    return error;
  }
  ADD_FAILURE() << "accepted: " << text;
  return InvalidInput("none", "none");
}

const std::string kCoupling = "coupling: \"nrel_upwind\"\n";

TEST(ModelFile, BundledPaperModelIsFrictionPressureAngleRotationAndSelfWeightOnTheUpwindCoupling) {
  const codec::ModelFile paper = bundled_model("paper");
  EXPECT_EQ(paper.name, "paper");
  EXPECT_EQ(paper.model.base_coupling().name, "nrel_upwind");
  ASSERT_EQ(paper.model.effects().size(), 3u);
  EXPECT_EQ(paper.model.effects()[0]->name(), "friction");
  EXPECT_DOUBLE_EQ(paper.model.effects()[0]->value("mu0"), 0.1);
  EXPECT_EQ(paper.model.effects()[1]->name(), "pressure_angle_rotation");
  EXPECT_EQ(paper.model.effects()[2]->name(), "self_weight");
  EXPECT_EQ(bundled_model("paper_downwind").model.base_coupling().name, "nrel_downwind");
}

TEST(ModelFile, UnknownEffectNamesItsEntryAndTheFile) {
  const InvalidInput error = error_of(kCoupling + "effects { name: \"fricton\" }");
  EXPECT_EQ(error.field(), "model.effects[0].fricton");
  EXPECT_NE(std::string(error.what()).find("bad.textproto"), std::string::npos) << error.what();
}

TEST(ModelFile, UnknownParameterNamesEffectAndParameter) {
  const InvalidInput error = error_of(
      kCoupling + "effects { name: \"friction\" parameters { name: \"mu9\" value: 0.1 } }");
  EXPECT_EQ(error.field(), "model.effects[0].friction.mu9");
}

TEST(ModelFile, ParameterOutsideItsBoundsNamesTheParameterAndItsRange) {
  const InvalidInput error = error_of(kCoupling + "effects { name: \"self_weight\" }\n" +
      "effects { name: \"friction\" parameters { name: \"mu0\" value: 0.9 } }");
  EXPECT_EQ(error.field(), "model.effects[1].friction.mu0");
  EXPECT_NE(std::string(error.what()).find("0.9"), std::string::npos) << error.what();
}

TEST(ModelFile, ParameterGivenTwiceIsAnErrorNotTheLastValue) {
  const InvalidInput error = error_of(kCoupling + "effects { name: \"friction\" " +
      "parameters { name: \"mu0\" value: 0.1 } parameters { name: \"mu0\" value: 0.2 } }");
  EXPECT_EQ(error.field(), "model.effects[0].parameters[1]");
}

TEST(ModelFile, EffectGivenTwiceIsAnError) {
  const InvalidInput error = error_of(kCoupling + "effects { name: \"self_weight\" }\n" +
                                      "effects { name: \"self_weight\" }");
  EXPECT_EQ(error.field(), "model.effects[1].name");
}

TEST(ModelFile, UnknownFieldNamesItWithLineAndColumn) {
  const InvalidInput error = error_of(kCoupling + "effect { name: \"friction\" }");
  EXPECT_EQ(error.field(), "model.effect");
  EXPECT_NE(std::string(error.what()).find("bad.textproto:2:"), std::string::npos) << error.what();
}

TEST(ModelFile, CouplingNotInTheCatalogueNamesTheField) {
  EXPECT_EQ(error_of("coupling: \"nrel_sideways\"").field(), "model.coupling");
  EXPECT_EQ(error_of("name: \"no coupling\"").field(), "model.coupling");
}

TEST(ModelFile, WrittenModelReadsBackToTheSamePredictions) {
  const codec::ModelFile paper = bundled_model("paper");
  const codec::ModelFile again = parse(
      codec::write_model_text("paper", "round trip", "nrel_upwind", paper.model));
  ASSERT_EQ(again.model.effects().size(), paper.model.effects().size());
  MeasurementSample sample;
  sample.torque_nm = 1.2e6;
  sample.misalignment_rad = 0.004;
  sample.direction_rad = 0.3;
  const SensorMoments a = paper.model.predict(sample).moments;
  const SensorMoments b = again.model.predict(sample).moments;
  EXPECT_EQ(a.y_nm, b.y_nm);  // every parameter written out exactly
  EXPECT_EQ(a.z_nm, b.z_nm);
}

TEST(ModelFile, ContinuousQuarterSumsAreReadWrittenAndReadBack) {
  // Issue 8: contact { continuous_quarter_sums } selects the continuous eqs 13 and 42-43.
  const std::string text = kCoupling + "effects { name: \"friction\" }\n";
  EXPECT_FALSE(parse(text).model.options().continuous_quarter_sums);  // the paper's form
  const codec::ModelFile continuous = parse(text + "contact { continuous_quarter_sums: true }");
  EXPECT_TRUE(continuous.model.options().continuous_quarter_sums);
  const std::string written =
      codec::write_model_text("continuous", "round trip", "nrel_upwind", continuous.model);
  EXPECT_NE(written.find("continuous_quarter_sums: true"), std::string::npos) << written;
  const codec::ModelFile again = parse(written);
  EXPECT_TRUE(again.model.options().continuous_quarter_sums);
  EXPECT_FALSE(parse(codec::write_model_text("paper", "", "nrel_upwind", parse(text).model))
                   .model.options()
                   .continuous_quarter_sums);
  // The flag reaches the predictions: same as read, different from the paper's form.
  MeasurementSample sample;
  sample.torque_nm = 1.2e6;
  sample.misalignment_rad = 0.004;
  EXPECT_EQ(again.model.predict(sample).moments.y_nm, continuous.model.predict(sample).moments.y_nm);
  EXPECT_NE(again.model.predict(sample).moments.y_nm,
            parse(text).model.predict(sample).moments.y_nm);
}

}  // namespace
}  // namespace gc
