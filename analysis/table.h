// Plain-text tables for the human-readable output: a header row (with units) and aligned
// columns, printed with fmt.
#pragma once

#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

namespace gc::analysis {

class Table {
 public:
  explicit Table(std::vector<std::string> headers);

  void add_row(std::vector<std::string> cells);
  /// A row of a quantity table (headers quantity | value | unit).
  void add_quantity(std::string_view quantity, double value, std::string_view unit);
  void add_quantity(std::string_view quantity, std::string_view value, std::string_view unit);
  void print(std::FILE* out) const;

 private:
  std::vector<std::string> headers_;
  std::vector<std::vector<std::string>> rows_;
};

/// A quantity table: headers "quantity", "value", "unit".
Table quantity_table();

/// Six significant digits, as tables show numbers ("1.5e+06", "0.000123").
std::string format_number(double value);

}  // namespace gc::analysis
