// The plain walk over a row (analysis/plain_csv_row.h): it reads what the general tokenizer and
// parse_double read, to the bit, and gives up on everything else, so that a bad row is still
// worded by the general reader (tests/analysis/recording_reader_test.cc's BadRows).
#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "analysis/csv_fields.h"
#include "analysis/number_text.h"
#include "analysis/plain_csv_row.h"

namespace gc::analysis {
namespace {

using Use = CellUse;

bool read(const std::string& row, const std::vector<Use>& uses, std::vector<double>& values) {
  values.assign(static_cast<std::size_t>(std::count(uses.begin(), uses.end(), Use::convert)), 0.0);
  return read_plain_row(row, uses, values);
}

TEST(PlainCsvRow, ReadsConvertedFieldsInOrderAndSkipsTheOthers) {
  std::vector<double> values;
  ASSERT_TRUE(read("0.01,150010.2,any text,-140023.89056638646,7,1e-05",
                   {Use::convert, Use::convert, Use::skip, Use::convert, Use::check, Use::convert}, values));
  EXPECT_EQ(values, (std::vector<double>{0.01, 150010.2, -140023.89056638646, 1e-05}));
  ASSERT_TRUE(read(",5,", {Use::skip, Use::convert, Use::skip}, values));  // empty skipped fields
  EXPECT_EQ(values, std::vector<double>{5.0});
}

// Each of these the general reader reads (a quoted or blank-padded number, a '+') or words as
// a problem (the rest): the walk leaves them all to it.
TEST(PlainCsvRow, GivesUpOnAnythingButPlainFields) {
  const std::vector<Use> uses{Use::convert, Use::check, Use::skip};
  std::vector<double> values;
  ASSERT_TRUE(read("1,2,x", uses, values));
  for (const char* row : {"\"1\",2,x", " 1,2,x", "1 ,2,x", "+1,2,x", ",2,x", "nan,2,x", "inf,2,x",
                          "-inf,2,x", "1e400,2,x", "1x,2,x", "1e,2,x", "0x10,2,x", "1,2", "1,2,x,",
                          "1,2,x,y", "1,\"2\",x", "1,+2,x", "1,,x", "1,1e100,x", "1,2 ,x",
                          "1,2,\"x,y\"", "1,2,a\"b", "1;2;x", ""}) {
    EXPECT_FALSE(read(row, uses, values)) << row;
  }
}

// Random rows built of plain and unusual cells: where the walk reads a row, the general
// tokenizer and parse_double read the same values, and vouch for its checked fields.
TEST(PlainCsvRow, AgreesWithTheGeneralTokenizerOnRandomRows) {
  const std::array<const char*, 22> cells{
      "0", "-140023.89056638646", "0.0039317337931164915", "1e-05", "3.5E+06", "12", "-0.0",
      "1e300", "1e100", "", " 1", "1 ", "+1", "\"2\"", "nan", "inf", "1.5x", "a", "1,5", "\"a,b\"",
      "2.", ".5"};
  const std::vector<Use> uses{Use::convert, Use::skip, Use::check, Use::convert, Use::convert};
  std::mt19937 random(11);
  std::uniform_int_distribution<std::size_t> pick(0, cells.size() - 1);
  int read_plain = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    std::string row;
    for (std::size_t field = 0; field < uses.size(); ++field) row += (field ? "," : "") + std::string(cells[pick(random)]);
    std::vector<double> values;
    if (!read(row, uses, values)) continue;
    ++read_plain;
    CsvFields fields;
    ASSERT_FALSE(fields.split(row)) << row;
    ASSERT_EQ(fields.size(), uses.size()) << row;
    std::size_t next = 0;
    for (std::size_t field = 0; field < uses.size(); ++field) {
      if (uses[field] == Use::check) EXPECT_TRUE(plainly_moderate_number(fields[field])) << row;
      if (uses[field] != Use::convert) continue;
      const std::optional<double> value = parse_double(fields[field]);
      ASSERT_TRUE(value) << row;
      EXPECT_EQ(std::bit_cast<std::uint64_t>(*value), std::bit_cast<std::uint64_t>(values[next++])) << row;
    }
  }
  EXPECT_GT(read_plain, 100);  // the plain rows were tried, not only the others
}

}  // namespace
}  // namespace gc::analysis
