#include "analysis/csv_fields.h"

#include <fmt/format.h>

#include "analysis/number_text.h"

namespace gc::analysis {
namespace {

constexpr std::string_view kByteOrderMark = "\xEF\xBB\xBF";

// A quoted field starting at `text[0] == '"'`: its value (quotes undone) appended to `out`.
// Returns the length consumed, through the closing quote, or npos when the quote stays open.
std::size_t unquote(std::string_view text, std::string& out) {
  for (std::size_t i = 1; i < text.size(); ++i) {
    if (text[i] != '"') {
      out += text[i];
    } else if (i + 1 < text.size() && text[i + 1] == '"') {
      out += '"';
      ++i;
    } else {
      return i + 1;
    }
  }
  return std::string_view::npos;
}

}  // namespace

std::string_view record_text(std::string_view line, long line_number) {
  if (line_number == 1 && line.starts_with(kByteOrderMark)) line.remove_prefix(kByteOrderMark.size());
  if (line.ends_with('\r')) line.remove_suffix(1);
  return trim(line).empty() ? std::string_view() : line;
}

bool next_csv_line(std::istream& in, std::string& line, long& line_number) {
  while (std::getline(in, line)) {
    const std::string_view record = record_text(line, ++line_number);
    if (record.empty()) continue;
    const auto start = static_cast<std::size_t>(record.data() - line.data());
    line.resize(start + record.size());
    line.erase(0, start);
    return true;
  }
  return false;
}

std::optional<std::string> CsvFields::split(std::string_view line) {
  fields_.clear();
  unquoted_.clear();
  // Unquoting never lengthens text: with this capacity the views into unquoted_ stay valid.
  unquoted_.reserve(line.size());
  std::size_t field_number = 1;
  for (;; ++field_number) {
    const std::string_view rest = trim_start(line);
    if (rest.starts_with('"')) {
      const std::size_t start = unquoted_.size();
      const std::size_t used = unquote(rest, unquoted_);
      if (used == std::string_view::npos) {
        return fmt::format("field {}: the quote it opens is not closed", field_number);
      }
      fields_.push_back(std::string_view(unquoted_).substr(start));
      line = trim_start(rest.substr(used));
      if (!line.empty() && line.front() != ',') {
        return fmt::format("field {}: text after its closing quote", field_number);
      }
    } else {
      const auto comma = line.find(',');
      fields_.push_back(trim(line.substr(0, comma)));
      line = comma == std::string_view::npos ? std::string_view() : line.substr(comma);
    }
    if (line.empty()) return std::nullopt;
    line.remove_prefix(1);  // the comma
  }
}

void append_csv_field(std::string& out, std::string_view field) {
  if (field.find_first_of(",\"\n\r") == std::string_view::npos) {
    out += field;
    return;
  }
  out += '"';
  for (char c : field) {
    if (c == '"') out += '"';
    out += c;
  }
  out += '"';
}

}  // namespace gc::analysis
