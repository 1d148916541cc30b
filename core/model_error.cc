#include "core/model_error.h"

#include <cmath>
#include <sstream>

namespace gc {
namespace {

std::string format_value(double value) {
  std::ostringstream out;
  out.precision(17);
  out << value;
  return out.str();
}

std::string describe(const std::string& field, double value, const std::string& allowed) {
  return field + " = " + format_value(value) + " is out of range: allowed " + allowed;
}

}  // namespace

InvalidInput::InvalidInput(std::string field, double value, std::string allowed)
    : ModelError(describe(field, value, allowed)), field_(std::move(field)) {}

InvalidInput::InvalidInput(std::string field, std::string message)
    : ModelError(field + ": " + message), field_(std::move(field)) {}

void require_in_range(const std::string& field, double value, double lo, double hi) {
  if (!std::isfinite(value) || value < lo || value > hi) {
    throw InvalidInput(field, value, "[" + format_value(lo) + ", " + format_value(hi) + "]");
  }
}

void require_positive(const std::string& field, double value) {
  if (!std::isfinite(value) || value <= 0.0) {
    throw InvalidInput(field, value, "a finite value > 0");
  }
}

void require_non_negative(const std::string& field, double value) {
  if (!std::isfinite(value) || value < 0.0) {
    throw InvalidInput(field, value, "a finite value >= 0");
  }
}

void require_finite(const std::string& field, double value) {
  if (!std::isfinite(value)) throw InvalidInput(field, value, "a finite number");
}

}  // namespace gc
