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

/// True when `text` is plainly a number parse_double reads as finite and below 1e140 in
/// magnitude, told from its characters without converting it (a tenth of the time): at most 40
/// of them, as [-]digits[.digits][e|E[+|-]d[d]]. False tells nothing: convert it to know.
bool plainly_moderate_number(std::string_view text);
/// The end of the plainly moderate number (as plainly_moderate_number) that [begin, end) starts
/// with, or nullptr when it starts with none: a cell told where it lies, without finding its end first.
const char* plain_moderate_number_end(const char* begin, const char* end);

/// Appends the shortest round-trip text of `value` to `out`.
void append_number(std::string& out, double value);
void append_number(std::string& out, long value);

// Inline: trimmed three times a cell (split, its field, the number), they were a tenth of
// reading a recording as calls. A loop, not find_first_not_of(" \t\r"): that asks memchr of
// the set for every character.
inline bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }

/// `text` without leading blanks.
inline std::string_view trim_start(std::string_view text) {
  std::size_t first = 0;
  while (first < text.size() && is_blank(text[first])) ++first;
  return text.substr(first);
}

/// `text` without leading and trailing blanks (spaces, tabs, '\r').
inline std::string_view trim(std::string_view text) {
  text = trim_start(text);
  std::size_t end = text.size();
  while (end > 0 && is_blank(text[end - 1])) --end;
  return text.substr(0, end);
}

}  // namespace gc::analysis
