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

std::optional<double> parse_double(std::string_view text) { return parse_whole<double>(text); }

const char* plain_moderate_number_end(const char* begin, const char* end) {
  constexpr std::size_t kMostCharacters = 40, kMostExponentDigits = 2;
  const char* at = begin;
  if (at != end && *at == '-') ++at;
  const auto digits = [&] {
    const char* start = at;
    while (at != end && *at >= '0' && *at <= '9') ++at;
    return static_cast<std::size_t>(at - start);
  };
  if (digits() == 0) return nullptr;
  if (at != end && *at == '.' && (++at, digits() == 0)) return nullptr;
  if (at != end && (*at == 'e' || *at == 'E')) {
    ++at;
    if (at != end && (*at == '+' || *at == '-')) ++at;
    const std::size_t exponent_digits = digits();
    if (exponent_digits == 0 || exponent_digits > kMostExponentDigits) return nullptr;
  }
  return static_cast<std::size_t>(at - begin) <= kMostCharacters ? at : nullptr;
}

bool plainly_moderate_number(std::string_view text) {
  const char* end = text.data() + text.size();
  return plain_moderate_number_end(text.data(), end) == end;
}

std::optional<int> parse_int(std::string_view text) { return parse_whole<int>(text); }

void append_number(std::string& out, double value) { append_shortest(out, value); }
void append_number(std::string& out, long value) { append_shortest(out, value); }

}  // namespace gc::analysis
