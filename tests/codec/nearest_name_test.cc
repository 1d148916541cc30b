// The "did you mean" of every edge's name errors (codec/nearest_name.h, issue 39).
#include "codec/nearest_name.h"

#include <gtest/gtest.h>

namespace gc::codec {
namespace {

// Hand counts: one insertion, one substitution, one swap of neighbours, case ignored.
TEST(EditDistance, CountsInsertionsSubstitutionsAndNeighbourSwapsAsOneEdit) {
  EXPECT_EQ(edit_distance("papr", "paper"), 1u);
  EXPECT_EQ(edit_distance("nrel_dowmwind", "nrel_downwind"), 1u);
  EXPECT_EQ(edit_distance("paepr", "paper"), 1u);
  EXPECT_EQ(edit_distance("PAPER", "paper"), 0u);
  EXPECT_EQ(edit_distance("", "abc"), 3u);
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);
}

TEST(NearestName, SuggestsOnlyANameNearEnoughToBeATypo) {
  const std::vector<std::string> models = {"paper", "paper_downwind"};
  EXPECT_EQ(nearest_name("papr", models), "paper");
  EXPECT_EQ(nearest_name("paper_dowwind", models), "paper_downwind");
  EXPECT_EQ(nearest_name("friction", models), "");   // far from both
  EXPECT_EQ(nearest_name("paper", models), "");      // not misspelt
  EXPECT_EQ(did_you_mean("papr", models), "; did you mean 'paper'?");
  EXPECT_EQ(did_you_mean("xyz", models), "");
}

TEST(NearestName, SuggestsTheLibrarysEffectForAMisspeltOne) {
  EXPECT_EQ(did_you_mean_effect("eccentricty"), "; did you mean 'eccentricity'?");
  EXPECT_EQ(did_you_mean_effect("fricton"), "; did you mean 'friction'?");
  EXPECT_EQ(did_you_mean_effect("gravity_well"), "");
}

}  // namespace
}  // namespace gc::codec
