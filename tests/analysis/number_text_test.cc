// Numbers in and out of CSV text: whole fields only, shortest round-trip output.
#include <cmath>
#include <cstdlib>
#include <random>
#include <regex>
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

// Against the rule written as a regular expression, on random text of digits and the bytes
// about them ('/' and ':', bytes that carry when 6 is added): digit runs of every length and
// place, eight at a time or one.
TEST(NumberText, PlainlyModerateNumbersAreTheDocumentedForm) {
  const std::regex form("-?[0-9]+(\\.[0-9]+)?([eE][+-]?[0-9]{1,2})?");
  const std::string alphabet = "0123456789012345678901234567890123456789.eE-+/:\xfa\xff ";
  std::mt19937 random(17);
  std::uniform_int_distribution<std::size_t> length(0, 45), pick(0, alphabet.size() - 1);
  for (int trial = 0; trial < 200000; ++trial) {
    std::string text(length(random), '0');
    for (char& c : text) c = trial % 2 ? alphabet[pick(random) % 40] : alphabet[pick(random)];
    if (trial % 3 == 0 && !text.empty()) text[pick(random) % text.size()] = '.';
    const bool expected = text.size() <= 40 && std::regex_match(text, form);
    ASSERT_EQ(plainly_moderate_number(text), expected) << text;
  }
}

}  // namespace
}  // namespace gc::analysis
