#include "core/model_error.h"

#include <cmath>
#include <sstream>

namespace gc {
namespace {

std::string describe(const std::string& field, double value, const std::string& allowed) {
  return field + " = " + format_precise(value) + " is out of range: allowed " + allowed;
}

}  // namespace

// Ten significant digits: what a user typed reads back as typed ("-0.1", not
// "-0.10000000000000001"), and values differing in the tenth digit still differ.
std::string format_precise(double value) {
  std::ostringstream out;
  out.precision(10);
  out << value;
  return out.str();
}

std::string format_number(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

InvalidInput::InvalidInput(std::string field, double value, std::string allowed)
    : ModelError(describe(field, value, allowed)), field_(std::move(field)) {}

InvalidInput::InvalidInput(std::string field, std::string message)
    : ModelError(field + ": " + message), field_(std::move(field)) {}

void require_in_range(std::string_view field, double value, double lo, double hi) {
  if (!std::isfinite(value) || value < lo || value > hi) {
    throw InvalidInput(std::string(field), value, "[" + format_precise(lo) + ", " + format_precise(hi) + "]");
  }
}

void require_positive(std::string_view field, double value) {
  if (!std::isfinite(value) || value <= 0.0) {
    throw InvalidInput(std::string(field), value, "a finite value > 0");
  }
}

void require_non_negative(std::string_view field, double value) {
  if (!std::isfinite(value) || value < 0.0) {
    throw InvalidInput(std::string(field), value, "a finite value >= 0");
  }
}

void require_finite(std::string_view field, double value) {
  if (!std::isfinite(value)) throw InvalidInput(std::string(field), value, "a finite number");
}

}  // namespace gc
