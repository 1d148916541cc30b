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

}  // namespace
}  // namespace gc::analysis
