#include "analysis/table.h"

#include <algorithm>

#include <fmt/format.h>

namespace gc::analysis {
namespace {

// Code points, not bytes: units such as "N·m" hold a two-byte character.
std::size_t display_width(std::string_view text) {
  return static_cast<std::size_t>(
      std::count_if(text.begin(), text.end(), [](char c) { return (c & 0xC0) != 0x80; }));
}

}  // namespace

Table::Table(std::vector<std::string> headers) : headers_(std::move(headers)) {}

void Table::add_row(std::vector<std::string> cells) {
  cells.resize(headers_.size());
  rows_.push_back(std::move(cells));
}

void Table::add_quantity(std::string_view quantity, double value, std::string_view unit) {
  add_quantity(quantity, format_number(value), unit);
}

void Table::add_quantity(std::string_view quantity, std::string_view value,
                         std::string_view unit) {
  add_row({std::string(quantity), std::string(value), std::string(unit)});
}

void Table::print(std::FILE* out) const {
  std::vector<std::size_t> widths(headers_.size());
  for (std::size_t c = 0; c < headers_.size(); ++c) {
    widths[c] = display_width(headers_[c]);
    for (const auto& row : rows_) widths[c] = std::max(widths[c], display_width(row[c]));
  }
  const auto print_row = [&](const std::vector<std::string>& cells) {
    std::string line;
    for (std::size_t c = 0; c < cells.size(); ++c) {
      line += cells[c];
      line.append(widths[c] - display_width(cells[c]) + 2, ' ');
    }
    while (!line.empty() && line.back() == ' ') line.pop_back();
    fmt::print(out, "{}\n", line);
  };
  print_row(headers_);
  std::vector<std::string> rule;
  for (std::size_t width : widths) rule.emplace_back(width, '-');
  print_row(rule);
  for (const auto& row : rows_) print_row(row);
}

Table quantity_table() { return Table({"quantity", "value", "unit"}); }

std::string format_number(double value) { return fmt::format("{:.6g}", value); }

}  // namespace gc::analysis
