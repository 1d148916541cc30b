// The CLI's small shared pieces: flag parsing, number text, tables.
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "clients/cli/command_line.h"
#include "clients/cli/number_text.h"
#include "clients/cli/table.h"

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

TEST(NumberText, ParsesWholeFieldsOnly) {
  EXPECT_EQ(parse_double(" +1.5 "), 1.5);
  EXPECT_EQ(parse_double("-2e-3\r"), -2e-3);
  EXPECT_FALSE(parse_double("1.5x"));
  EXPECT_FALSE(parse_double(""));
  EXPECT_FALSE(parse_double("1,5"));
  EXPECT_EQ(parse_int("42"), 42);
  EXPECT_FALSE(parse_int("4.2"));
  EXPECT_FALSE(parse_int("99999999999"));
}

TEST(NumberText, PrintsDoublesThatReadBackExactly) {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> exponent(-300.0, 300.0);
  std::uniform_real_distribution<double> mantissa(-10.0, 10.0);
  for (int i = 0; i < 100000; ++i) {
    const double value = mantissa(random) * std::pow(10.0, exponent(random));
    std::string text;
    append_number(text, value);
    ASSERT_EQ(std::strtod(text.c_str(), nullptr), value) << text;
  }
  std::string text;
  append_number(text, 0.1);
  EXPECT_EQ(text, "0.1");  // shortest form, not 0.10000000000000001
}

TEST(Table, AlignsColumnsByCharactersNotBytes) {
  Table table({"quantity", "unit"});
  table.add_row({"torque", "N·m"});
  table.add_row({"misalignment", "deg"});
  char* buffer = nullptr;
  std::size_t size = 0;
  std::FILE* out = open_memstream(&buffer, &size);
  table.print(out);
  std::fclose(out);
  const std::string printed(buffer, size);
  std::free(buffer);
  EXPECT_EQ(printed,
            "quantity      unit\n"
            "------------  ----\n"
            "torque        N·m\n"
            "misalignment  deg\n");
}

}  // namespace
}  // namespace gc::cli
