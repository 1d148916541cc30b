// Flag parsing with CLI11 through the flag tables (number text and tables: tests/analysis/).
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "clients/cli/command_line.h"

namespace gc::cli {
namespace {

std::vector<FlagSpec> specs() {
  return {{"torque-nm", "N·m", "torque", std::nullopt, false, '\0', {"torque"}},
          {"direction-deg", "deg", "direction", "0"},
          {"jobs", "N", "threads", "1", false, 'j', {"threads"}},
          {"json", "", "json", std::nullopt, true},
          {"remote", "", "", std::nullopt, true, '\0', {}, "not here"},
          {"domain", "N", "", "0", false, '\0', {}, "not here either"}};
}

// The flags parsed from `args`; FAILs when --help was asked for.
struct Parsed {
  Flags flags{specs()};
  explicit Parsed(std::vector<const char*> args) {
    EXPECT_TRUE(parse_flags(flags, args));
  }
};

TEST(Flags, TakesSpaceAndEqualsFormsAndNegativeValues) {
  const Parsed parsed({"--torque-nm=1.5e6", "--direction-deg", "-30"});
  EXPECT_EQ(parsed.flags.number("torque-nm"), 1.5e6);
  EXPECT_EQ(parsed.flags.number("direction-deg"), -30.0);
  EXPECT_FALSE(parsed.flags.enabled("json"));
  EXPECT_EQ(parsed.flags.integer("jobs", 1, 8), 1);  // the default
  EXPECT_EQ(Parsed({"--torque-nm", "2", "--direction-deg=-5"}).flags.number("direction-deg"), -5.0);
}

TEST(Flags, AliasesSetTheSameFlag) {
  EXPECT_EQ(Parsed({"--torque", "7"}).flags.number("torque-nm"), 7.0);
  EXPECT_EQ(Parsed({"--torque=8"}).flags.number("torque-nm"), 8.0);
  EXPECT_EQ(Parsed({"--torque", "1", "--threads=5"}).flags.integer("jobs", 1, 8), 5);
}

TEST(Flags, ShortFlagTakesAttachedOrSeparateValue) {
  EXPECT_EQ(Parsed({"--torque-nm", "1", "-j3"}).flags.integer("jobs", 1, 8), 3);
  EXPECT_EQ(Parsed({"--torque-nm", "1", "-j", "4"}).flags.integer("jobs", 1, 8), 4);
  EXPECT_EQ(Parsed({"--torque-nm", "1", "--jobs=6"}).flags.integer("jobs", 1, 8), 6);
}

TEST(Flags, SwitchIsSetWithoutValue) {
  EXPECT_TRUE(Parsed({"--json", "--torque-nm", "1"}).flags.enabled("json"));
}

UsageError parse_error(std::vector<const char*> args) {
  Flags flags(specs());
  try {
    parse_flags(flags, args);
  } catch (const UsageError& error) {
    return error;
  }
  ADD_FAILURE() << "no UsageError";
  return UsageError("");
}

TEST(Flags, RejectsUnknownRepeatedMissingAndValuelessFlags) {
  EXPECT_STREQ(parse_error({"--torque-nm", "1", "--speed", "2"}).what(),
               "unknown flag --speed (see --help)");
  EXPECT_STREQ(parse_error({"torque", "1"}).what(), "unexpected argument 'torque'");
  EXPECT_STREQ(parse_error({"--torque-nm", "1", "--torque", "2"}).what(),
               "--torque-nm given 2 times (at most once)");
  EXPECT_STREQ(parse_error({"--torque-nm"}).what(), "--torque-nm: 1 required N·m missing");
  EXPECT_STREQ(parse_error({"--direction-deg", "3"}).what(), "--torque-nm is required (torque)");
}

TEST(Flags, RefusedFlagsSayWhyAndAreLeftOutOfTheHelp) {
  EXPECT_STREQ(parse_error({"--torque-nm", "1", "--remote"}).what(), "--remote: not here");
  EXPECT_STREQ(parse_error({"--torque-nm", "1", "--domain=3"}).what(),
               "--domain: not here either");
  Flags flags(specs());
  EXPECT_FALSE(flags.has("remote"));
  EXPECT_FALSE(flags.enabled("remote"));
  const std::string help = usage_text("test", "summary", specs());
  EXPECT_EQ(help.find("--remote"), std::string::npos) << help;
  EXPECT_NE(help.find("--torque-nm <N·m>"), std::string::npos) << help;
  EXPECT_NE(help.find("alias --torque"), std::string::npos) << help;
  EXPECT_NE(help.find("-j, --jobs <N>"), std::string::npos) << help;
}

TEST(Flags, HelpNeedsNoRequiredFlag) {
  Flags flags(specs());
  EXPECT_FALSE(parse_flags(flags, std::vector<const char*>{"--help"}));
}

TEST(Flags, NumberAndIntegerErrorsNameTheFlag) {
  const Parsed parsed({"--torque-nm", "12abc", "-j", "9"});
  try {
    parsed.flags.number("torque-nm");
    FAIL();
  } catch (const UsageError& error) {
    EXPECT_STREQ(error.what(), "--torque-nm '12abc' is not a number (torque)");
  }
  try {
    parsed.flags.integer("jobs", 1, 8);
    FAIL();
  } catch (const UsageError& error) {
    EXPECT_STREQ(error.what(), "--jobs 9 is out of range: allowed a whole number in [1, 8]");
  }
}

}  // namespace
}  // namespace gc::cli
