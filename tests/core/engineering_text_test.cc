// Engineering notation in human text: three significant digits under a power-of-1000 prefix.
#include <cmath>

#include <gtest/gtest.h>

#include "core/engineering_text.h"

namespace gc {
namespace {

TEST(EngineeringText, ThreeSignificantDigitsUnderAPrefix) {
  EXPECT_EQ(engineering_text(1.5e6, "N·m"), "1.50 MN·m");
  EXPECT_EQ(engineering_text(2.04e4, "N·m"), "20.4 kN·m");
  EXPECT_EQ(engineering_text(251.0, "N·m"), "251 N·m");
  EXPECT_EQ(engineering_text(-1830.0, "N·m"), "-1.83 kN·m");
  EXPECT_EQ(engineering_text(0.0015, "rad"), "1.50 mrad");
  EXPECT_EQ(engineering_text(999.96, "N·m"), "1.00 kN·m");  // rounds up into the next prefix
  EXPECT_EQ(engineering_text(0.0, "N·m"), "0.00 N·m");
  EXPECT_EQ(engineering_text(NAN, "N·m"), "nan N·m");
}

TEST(EngineeringText, UnitsWithoutPrefixesKeepThreeDigits) {
  EXPECT_EQ(engineering_text(0.4321, "deg"), "0.432 deg");
  EXPECT_EQ(engineering_text(1234.0, "-"), "1234");  // "-": no unit
  EXPECT_EQ(engineering_text(0.061, ""), "0.0610");
}

TEST(EngineeringText, AReferenceSetsPrefixAndDecimals) {
  EXPECT_EQ(engineering_text(251.0, "N·m", 2.04e4), "0.3 kN·m");
  EXPECT_EQ(engineering_text(18200.0, "N·m", 2.04e4), "18.2 kN·m");
}

TEST(EngineeringText, RangesShareOnePrefixAndCollapseWhenEqual) {
  EXPECT_EQ(engineering_range(1.5e6, 1.8e6, "N·m"), "1.50-1.80 MN·m");
  EXPECT_EQ(engineering_range(1.5e5, 1.5e6, "N·m"), "0.15-1.50 MN·m");
  EXPECT_EQ(engineering_range(1.501e6, 1.499e6, "N·m"), "1.50 MN·m");
  EXPECT_EQ(engineering_range(-500.0, 750.0, "N·m"), "-500 to 750 N·m");
  // Under a prefix of the caller's (worst regions: torques in kN·m, as the moments beside them).
  EXPECT_EQ(engineering_range(0.625e6, 2.2e6, "N·m", 1e3), "625-2200 kN·m");
  EXPECT_EQ(engineering_range(0.15e6, 0.3e6, "N·m", 1e3), "150-300 kN·m");
  EXPECT_EQ(engineering_range(5e3, 9.5e3, "N·m", 1e3), "5.00-9.50 kN·m");
}

}  // namespace
}  // namespace gc
