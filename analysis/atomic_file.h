// Output files that are whole or absent: a failed --html or --write-model left a 0-byte file
// that looked like a report. The text goes to a temporary file beside the target, renamed over
// it only once written and flushed.
#pragma once

#include <filesystem>
#include <string_view>

namespace gc::analysis {

/// Writes `text` to `path` or, on failure, leaves `path` as it was. Throws std::runtime_error
/// naming `what` (e.g. "--html") and the path.
void write_file_atomically(const std::filesystem::path& path, std::string_view text,
                           std::string_view what);

}  // namespace gc::analysis
