// The flags and notes every subcommand that reads a recording shares (validate, diagnose):
// --columns, and the ignored columns and scale warnings on standard error.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "analysis/recording_csv.h"
#include "clients/cli/command_line.h"

namespace gc::cli {

/// --columns NAME=HEADER,...: the file's columns under other names (docs/recordings.md).
FlagSpec columns_flag();

/// --negate QUANTITY,...: read these columns with their sign flipped (docs/recordings.md).
FlagSpec negate_flag();
/// The quantities --negate gives. Throws analysis::FormatError naming one that is no quantity.
std::vector<analysis::Quantity> negated_quantities(const Flags& flags);

/// --force-scale: run validate or diagnose on a recording whose moments are 1000 times the
/// model's (refused otherwise, analysis/scale_check.h).
FlagSpec force_scale_flag();

/// The renames --columns gives. Throws analysis::FormatError naming a malformed item.
std::vector<analysis::ColumnRename> column_renames(const Flags& flags);

/// "gearcoupling <subcommand>: note: ignored N columns ..." and one "warning:" line per scale
/// warning, on standard error: read by a user of --json too.
void print_recording_notes(std::string_view subcommand, const std::vector<std::string>& ignored_columns,
                           const std::vector<std::string>& warnings);

}  // namespace gc::cli
