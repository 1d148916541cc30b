// validate's result as data: zero compared samples is an error, not a perfect fit; the
// report's one colour scale and noise level.
#include <string>

#include <gtest/gtest.h>

#include "analysis/report_scale.h"
#include "analysis/validation_result.h"
#include "core/model_error.h"

namespace gc::analysis {
namespace {

namespace v1 = gearcoupling::v1;

std::string compared_nothing_message(std::size_t rows, std::size_t excluded, std::size_t refused) {
  try {
    require_compared_samples("r.csv", "paper", 0, rows, excluded, refused,
                             "operating_point.misalignment_rad: beyond the jam angle");
  } catch (const InvalidInput& error) {
    EXPECT_EQ(error.field(), "recording");
    return error.what();
  }
  ADD_FAILURE() << "no error";
  return "";
}

TEST(RequireComparedSamples, SaysWhyNothingWasCompared) {
  EXPECT_NE(compared_nothing_message(0, 0, 0).find("r.csv: paper compared no sample: the file has no data rows"),
            std::string::npos);
  EXPECT_NE(compared_nothing_message(5, 5, 0).find("all 5 rows were excluded as malformed"), std::string::npos);
  const std::string refused = compared_nothing_message(7, 0, 7);
  EXPECT_NE(refused.find("the model refused all 7 samples read (first: operating_point.misalignment_rad"),
            std::string::npos) << refused;
  EXPECT_NO_THROW(require_compared_samples("r.csv", "paper", 1, 7, 0, 6, ""));
}

TEST(RequireComparedSamples, ChecksEveryModelOfAResult) {
  v1::ValidationResult result;
  result.set_recording("r.csv");
  result.set_recording_rows(3);
  result.add_models()->set_compared_samples(3);
  EXPECT_NO_THROW(require_compared_samples(result));
  v1::ModelValidation* added = result.add_models();
  added->set_model("paper + friction");
  added->set_rejected_samples(3);
  EXPECT_THROW(require_compared_samples(result), InvalidInput);
}

void add_cell(v1::ModelValidation& model, double msy_rmse_nm, double msz_rmse_nm, int count) {
  v1::ChannelErrorsRecord* cell = model.mutable_error_map()->add_cells();
  cell->mutable_msy()->set_rmse_nm(msy_rmse_nm);
  cell->mutable_msy()->set_count(count);
  cell->mutable_msz()->set_rmse_nm(msz_rmse_nm);
  cell->mutable_msz()->set_count(count);
}

// The before/after case of the report: 20 kN·m before, 2 kN·m after, on one scale.
TEST(ReportScale, IsTheWorstCellOfAllModelsAndChannels) {
  v1::ValidationResult result;
  v1::ModelValidation* before = result.add_models();
  add_cell(*before, 20e3, 5e3, 10);
  add_cell(*before, 99e3, 99e3, 0);   // an empty cell holds no error
  v1::ModelValidation* after = result.add_models();
  add_cell(*after, 2e3, 2.5e3, 10);
  EXPECT_EQ(colour_scale_max_nm(result), 20e3);
  EXPECT_EQ(colour_scale_max_nm(v1::ValidationResult()), 0.0);
}

TEST(ReportScale, NoiseLevelIsTheMedianOfTheModelsEstimates) {
  v1::ValidationResult result;
  for (const auto& [noise_y, noise_z] : {std::pair{2100.0, 1900.0}, std::pair{2000.0, 2600.0}}) {
    v1::ModelValidation* model = result.add_models();
    model->set_compared_samples(100);
    model->add_signatures()->set_noise_estimate_nm(noise_y);
    model->add_signatures()->set_noise_estimate_nm(noise_z);
  }
  result.add_models()->add_signatures()->set_noise_estimate_nm(1e9);  // compared nothing
  EXPECT_DOUBLE_EQ(noise_level_nm(result), 2050.0);  // median of 1900, 2000, 2100, 2600
  EXPECT_EQ(noise_level_nm(v1::ValidationResult()), 0.0);
}

}  // namespace
}  // namespace gc::analysis
