// Plain-text tables of the summaries.
#include <cstdio>
#include <cstdlib>
#include <string>

#include <gtest/gtest.h>

#include "analysis/table.h"

namespace gc::analysis {
namespace {

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
}  // namespace gc::analysis
