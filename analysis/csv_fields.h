// Fields of a CSV line: plain fields split at commas (no quoting on input), and RFC 4180
// quoting on output. Shared by the batch and recording formats.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace gc::cli {

/// The comma-separated fields of `line`, each trimmed, into `fields` (reusing its storage).
void split_fields(std::string_view line, std::vector<std::string_view>& fields);

/// RFC 4180: quote a field holding a comma, quote or line break; double its quotes.
void append_csv_field(std::string& out, std::string_view field);

}  // namespace gc::cli
