// Numbers in and out of text with std::from_chars / std::to_chars: locale-free, exact (the
// shortest text that reads back to the same double), and fast enough for a million CSV rows.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace gc::analysis {

/// The whole of `text` (surrounding blanks allowed, a leading '+' accepted) as a double, or
/// empty when it is not a number. "nan" and "inf" parse: the core rejects them by name.
std::optional<double> parse_double(std::string_view text);

/// The whole of `text` as an int, or empty.
std::optional<int> parse_int(std::string_view text);

/// Appends the shortest round-trip text of `value` to `out`.
void append_number(std::string& out, double value);
void append_number(std::string& out, long value);

/// `text` without leading and trailing blanks (spaces, tabs, '\r').
std::string_view trim(std::string_view text);
/// `text` without leading blanks.
std::string_view trim_start(std::string_view text);

}  // namespace gc::analysis
