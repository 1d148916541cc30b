#include "analysis/number_text.h"

#include <array>
#include <charconv>

namespace gc::analysis {
namespace {

template <typename Number>
std::optional<Number> parse_whole(std::string_view text) {
  text = trim(text);
  if (text.starts_with('+')) text.remove_prefix(1);
  if (text.empty()) return std::nullopt;
  Number value{};
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

template <typename Number>
void append_shortest(std::string& out, Number value) {
  std::array<char, 32> buffer;  // 24 characters hold any double's shortest form
  const auto [end, error] = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
  out.append(buffer.data(), end);
}

}  // namespace

namespace {
// A loop, not find_first_not_of(" \t\r"): that asks memchr of the set for every character,
// and trimming every cell was a fifth of reading a recording.
bool blank(char c) { return c == ' ' || c == '\t' || c == '\r'; }
}  // namespace

std::string_view trim_start(std::string_view text) {
  std::size_t first = 0;
  while (first < text.size() && blank(text[first])) ++first;
  return text.substr(first);
}

std::string_view trim(std::string_view text) {
  text = trim_start(text);
  std::size_t end = text.size();
  while (end > 0 && blank(text[end - 1])) --end;
  return text.substr(0, end);
}

std::optional<double> parse_double(std::string_view text) { return parse_whole<double>(text); }
std::optional<int> parse_int(std::string_view text) { return parse_whole<int>(text); }

void append_number(std::string& out, double value) { append_shortest(out, value); }
void append_number(std::string& out, long value) { append_shortest(out, value); }

}  // namespace gc::analysis
