#include "clients/cli/recording_flags.h"

#include <cstdio>

#include <fmt/format.h>

namespace gc::cli {

FlagSpec columns_flag() {
  return {"columns", "NAME=HEADER,...",
          "read the file's column HEADER as NAME of docs/recordings.md, e.g. msy_knm=Ch3_kNm", ""};
}

FlagSpec negate_flag() {
  return {"negate", "QUANTITY,...",
          "read these quantities with their sign flipped, e.g. torque for a dyno that logs the "
          "drive torque negative",
          ""};
}

std::vector<analysis::Quantity> negated_quantities(const Flags& flags) {
  const std::string& text = flags.text("negate");
  if (text.empty()) return {};
  return analysis::parse_negated_quantities(text);
}

FlagSpec force_scale_flag() {
  return {"force-scale", "",
          "run even when a moment channel is 1000 times the model's (kN·m under _nm?), "
          "which is refused otherwise",
          std::nullopt, true};
}

std::vector<analysis::ColumnRename> column_renames(const Flags& flags) {
  const std::string& text = flags.text("columns");
  if (text.empty()) return {};
  return analysis::parse_column_renames(text);
}

void print_recording_notes(std::string_view subcommand, const std::vector<std::string>& ignored_columns,
                           const std::vector<std::string>& warnings) {
  if (!ignored_columns.empty()) {
    std::string names;
    for (const std::string& column : ignored_columns) names += (names.empty() ? "" : ", ") + column;
    fmt::print(stderr, "gearcoupling {}: note: ignored {} column{} of no known quantity: {} "
               "(--columns NAME=HEADER reads one as a known column)\n", subcommand,
               ignored_columns.size(), ignored_columns.size() == 1 ? "" : "s", names);
  }
  for (const std::string& warning : warnings) {
    fmt::print(stderr, "gearcoupling {}: warning: {}\n", subcommand, warning);
  }
}

}  // namespace gc::cli
