// Flag parsing (number text and tables: tests/analysis/).
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "clients/cli/command_line.h"

namespace gc::cli {
namespace {

std::vector<FlagSpec> specs() {
  return {{"torque", "N·m", "torque", std::nullopt},
          {"direction-deg", "deg", "direction", "0"},
          {"jobs", "N", "threads", "1", false, 'j'},
          {"json", "", "json", std::nullopt, true}};
}

Flags parse(std::vector<const char*> args) { return Flags(specs(), args); }

TEST(Flags, TakesSpaceAndEqualsFormsAndNegativeValues) {
  const Flags flags = parse({"--torque=1.5e6", "--direction-deg", "-30"});
  EXPECT_EQ(flags.number("torque"), 1.5e6);
  EXPECT_EQ(flags.number("direction-deg"), -30.0);
  EXPECT_FALSE(flags.enabled("json"));
  EXPECT_EQ(flags.integer("jobs", 1, 8), 1);  // the default
}

TEST(Flags, ShortFlagTakesAttachedOrSeparateValue) {
  EXPECT_EQ(parse({"--torque", "1", "-j3"}).integer("jobs", 1, 8), 3);
  EXPECT_EQ(parse({"--torque", "1", "-j", "4"}).integer("jobs", 1, 8), 4);
}

TEST(Flags, SwitchIsSetWithoutValue) {
  EXPECT_TRUE(parse({"--json", "--torque", "1"}).enabled("json"));
  EXPECT_THROW(parse({"--json=yes", "--torque", "1"}), UsageError);
}

TEST(Flags, RejectsUnknownRepeatedMissingAndValuelessFlags) {
  EXPECT_THROW(parse({"--torque", "1", "--speed", "2"}), UsageError);
  EXPECT_THROW(parse({"--torque", "1", "--torque", "2"}), UsageError);
  EXPECT_THROW(parse({"--direction-deg", "3"}), UsageError);  // --torque is required
  EXPECT_THROW(parse({"--torque"}), UsageError);
  EXPECT_THROW(parse({"torque", "1"}), UsageError);
  try {
    parse({"--direction-deg", "3"});
  } catch (const UsageError& error) {
    EXPECT_STREQ(error.what(), "--torque is required (torque)");
  }
}

TEST(Flags, HelpNeedsNoRequiredFlag) { EXPECT_TRUE(parse({"--help"}).help_requested()); }

TEST(Flags, NumberAndIntegerErrorsNameTheFlag) {
  const Flags flags = parse({"--torque", "12abc", "-j", "9"});
  try {
    flags.number("torque");
    FAIL();
  } catch (const UsageError& error) {
    EXPECT_STREQ(error.what(), "--torque '12abc' is not a number (torque)");
  }
  try {
    flags.integer("jobs", 1, 8);
    FAIL();
  } catch (const UsageError& error) {
    EXPECT_STREQ(error.what(), "--jobs 9 is out of range: allowed a whole number in [1, 8]");
  }
}

}  // namespace
}  // namespace gc::cli
