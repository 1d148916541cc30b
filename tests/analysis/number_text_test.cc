// Numbers in and out of CSV text: whole fields only, shortest round-trip output.
#include <cmath>
#include <cstdlib>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "analysis/number_text.h"

namespace gc::analysis {
namespace {

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

// What plainly_moderate_number vouches for, parse_double reads as a finite number below 1e140;
// what it leaves to the conversion includes every form it is unsure of.
TEST(NumberText, PlainlyModerateNumbersParseFinite) {
  for (const char* text : {"0", "-140023.89056638646", "1e-05", "3.5E+06", "12345678901234567890.5",
                           "-9.99e99", "0.0039317337931164915"}) {
    EXPECT_TRUE(plainly_moderate_number(text)) << text;
    const std::optional<double> value = parse_double(text);
    ASSERT_TRUE(value) << text;
    EXPECT_TRUE(std::isfinite(*value) && std::abs(*value) < 1e140) << text;
  }
  for (const char* text : {"", "-", "+1", ".5", "5.", "1e", "1e+", "1e100", "1e308", "nan", "inf",
                           "-inf", "1,5", "1.5x", " 1", "1 ", "--1", "1e5.5", "0x10",
                           "1234567890123456789012345678901234567890.5"}) {
    EXPECT_FALSE(plainly_moderate_number(text)) << text;
  }
}

}  // namespace
}  // namespace gc::analysis
