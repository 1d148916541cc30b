// The one CSV tokenizer of recordings and batch input: lines (byte-order mark, CRLF, blank
// lines) and fields (trimming, quotes).
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "analysis/csv_fields.h"
#include "analysis/csv_line_reader.h"
#include "analysis/number_text.h"

namespace gc::analysis {
namespace {

struct Line {
  std::string text;
  long number;
  bool operator==(const Line&) const = default;
};

std::vector<Line> lines_of(const std::string& text) {
  std::istringstream in(text);
  std::vector<Line> lines;
  std::string line;
  long number = 0;
  while (next_csv_line(in, line, number)) lines.push_back({line, number});
  return lines;
}

// The block reader's lines, read twice: through to the end, then again from the second line
// on after a rewind.
std::vector<Line> block_lines_of(const std::string& text) {
  std::istringstream in(text);
  CsvLineReader reader(in);
  std::vector<Line> lines;
  CsvLine line;
  std::streamoff second = -1;
  long second_number = 0;
  while (reader.next(line)) {
    lines.push_back({std::string(reader.line_text(line)), line.line_number});
    if (lines.size() == 1) {
      second = reader.position();
      second_number = reader.line_number();
    }
    if (lines.size() % 3 == 0) reader.release();  // the rest stays readable across a release
  }
  EXPECT_TRUE(reader.at_end());
  if (second >= 0 && reader.rewind(second, second_number)) {
    std::size_t again = 1;
    while (reader.next(line)) {
      EXPECT_LT(again, lines.size());
      if (again >= lines.size()) break;
      EXPECT_EQ((Line{std::string(reader.line_text(line)), line.line_number}), lines[again++]);
    }
    EXPECT_EQ(again, lines.size());
  }
  return lines;
}

std::vector<std::string> fields_of(const std::string& line) {
  CsvFields fields;
  EXPECT_EQ(fields.split(line), std::nullopt) << line;
  return {fields.fields().begin(), fields.fields().end()};
}

TEST(CsvLines, ByteOrderMarkIsSkippedOnTheFirstLineOnly) {
  EXPECT_EQ(lines_of("\xEF\xBB\xBFtime_s,a\n\xEF\xBB\xBF" "1,2\n"),
            (std::vector<Line>{{"time_s,a", 1}, {"\xEF\xBB\xBF" "1,2", 2}}));
}

TEST(CsvLines, CarriageReturnsOfCrlfAreDropped) {
  EXPECT_EQ(lines_of("a,b\r\n1,2\r\n"), (std::vector<Line>{{"a,b", 1}, {"1,2", 2}}));
}

TEST(CsvLines, BlankLinesHoldNoRecordButCountInTheLineNumbers) {
  EXPECT_EQ(lines_of("\na,b\n\n \t\r\n1,2\n\n\r\n"), (std::vector<Line>{{"a,b", 2}, {"1,2", 5}}));
  EXPECT_TRUE(lines_of("").empty());
  EXPECT_TRUE(lines_of("\n\r\n").empty());
}

TEST(CsvFields, UnquotedFieldsAreTrimmed) {
  EXPECT_EQ(fields_of(" a , b\t,,c "), (std::vector<std::string>{"a", "b", "", "c"}));
  EXPECT_EQ(fields_of(""), (std::vector<std::string>{""}));
  EXPECT_EQ(fields_of("a,"), (std::vector<std::string>{"a", ""}));
}

TEST(CsvFields, QuotedFieldsKeepCommasBlanksAndDoubledQuotes) {
  EXPECT_EQ(fields_of(R"( "a, b" ,"say ""hi""", " x ",)"),
            (std::vector<std::string>{"a, b", R"(say "hi")", " x ", ""}));
  EXPECT_EQ(fields_of(R"("")"), (std::vector<std::string>{""}));
}

// "1.5" is a number in quotes; "1,5" is a field with a comma, which is not a number.
TEST(CsvFields, QuotedNumbersAreNumbersAndADecimalCommaIsNot) {
  const std::vector<std::string> fields = fields_of(R"("1.5","1,5",2)");
  ASSERT_EQ(fields.size(), 3u);
  EXPECT_EQ(parse_double(fields[0]), 1.5);
  EXPECT_EQ(parse_double(fields[1]), std::nullopt);
  EXPECT_EQ(parse_double(fields[2]), 2.0);
}

TEST(CsvFields, AQuoteLeftOpenOrTextAfterTheClosingQuoteIsNamed) {
  CsvFields fields;
  EXPECT_EQ(fields.split(R"(1,"2,3)"), "field 2: the quote it opens is not closed");
  EXPECT_EQ(fields.split(R"(1,"2"x,3)"), "field 2: text after its closing quote");
}

// Views into the splitter's storage stay valid across all fields of a line, however many
// were unquoted.
TEST(CsvFields, ManyQuotedFieldsStayIntact) {
  std::string line;
  std::vector<std::string> expected;
  for (int i = 0; i < 200; ++i) {
    if (i > 0) line += ',';
    line += "\"v\"\"";
    line += std::to_string(i);
    line += '"';
    expected.push_back("v\"" + std::to_string(i));
  }
  EXPECT_EQ(fields_of(line), expected);
}

TEST(CsvFields, OutputQuotingReadsBack) {
  std::string out;
  append_csv_field(out, R"(a, "b")");
  EXPECT_EQ(out, R"("a, ""b""")");
  EXPECT_EQ(fields_of(out), (std::vector<std::string>{R"(a, "b")"}));
}

// The block reader (validate's) gives next_csv_line's lines and numbers: a byte-order mark,
// CRLF, blank and blank-looking lines, no final line break, and a line longer than a block.
TEST(CsvLines, TheBlockReaderGivesTheLinesOfNextCsvLine) {
  const std::string long_line(3u << 20, '7');
  for (const std::string& text :
       {std::string("\xEF\xBB\xBFtime_s,a\r\n1,2\r\n\r\n \t\n3,4"), std::string("a\n\n\nb\n"),
        std::string(""), std::string("\n\n"), std::string("h\n") + long_line + "\n" + long_line + ",1",
        std::string("x,y\n1,2\n")}) {
    EXPECT_EQ(block_lines_of(text), lines_of(text)) << text.substr(0, 40);
  }
}

}  // namespace
}  // namespace gc::analysis
