#include "core/engineering_text.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>

namespace gc {
namespace {

struct Prefix {
  double scale;
  const char* symbol;
};

constexpr std::array<Prefix, 7> kPrefixes = {
    {{1e9, "G"}, {1e6, "M"}, {1e3, "k"}, {1.0, ""}, {1e-3, "m"}, {1e-6, "µ"}, {1e-9, "n"}}};

bool takes_prefix(std::string_view unit) { return !(unit.empty() || unit == "-" || unit == "deg"); }

// The prefix under which |reference| reads 1 to 999 (rounded to three digits: 999.7 is 1.00 k).
Prefix prefix_for(double reference, std::string_view unit) {
  const double magnitude = std::abs(reference);
  if (!takes_prefix(unit) || magnitude == 0.0 || !std::isfinite(magnitude)) return {1.0, ""};
  for (const Prefix& prefix : kPrefixes) {
    if (magnitude >= 0.9995 * prefix.scale) return prefix;
  }
  return kPrefixes.back();
}

// Decimals that give `reference / scale` three significant digits.
int decimals_for(double reference, double scale) {
  const double mantissa = std::abs(reference) / scale;
  if (mantissa == 0.0 || !std::isfinite(mantissa)) return 2;
  const int integer_digits = static_cast<int>(std::floor(std::log10(mantissa * 1.0005))) + 1;
  return std::clamp(3 - integer_digits, 0, 9);
}

std::string with_unit(const std::string& number, const Prefix& prefix, std::string_view unit) {
  std::string text = number;
  if (!unit.empty() && unit != "-") text += " " + std::string(prefix.symbol) + std::string(unit);
  return text;
}

std::string fixed(double value, int decimals) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
  return buffer;
}

}  // namespace

std::string engineering_text(double value, std::string_view unit) {
  return engineering_text(value, unit, value);
}

std::string engineering_text(double value, std::string_view unit, double reference) {
  if (!std::isfinite(value)) return with_unit(std::isnan(value) ? "nan" : value > 0 ? "inf" : "-inf", {1.0, ""}, unit);
  const Prefix prefix = prefix_for(reference, unit);
  return with_unit(fixed(value / prefix.scale, decimals_for(reference, prefix.scale)), prefix, unit);
}

std::string engineering_range(double lower, double upper, std::string_view unit) {
  return engineering_range(lower, upper, unit,
                           prefix_for(std::max(std::abs(lower), std::abs(upper)), unit).scale);
}

std::string engineering_range(double lower, double upper, std::string_view unit, double scale) {
  const double reference = std::max(std::abs(lower), std::abs(upper));
  const Prefix prefix = prefix_for(scale, unit);
  const int decimals = decimals_for(reference, prefix.scale);
  const std::string low = fixed(lower / prefix.scale, decimals);
  const std::string high = fixed(upper / prefix.scale, decimals);
  // "-0.50 to 0.50": a hyphen between signed numbers would read as a minus.
  const char* separator = lower < 0.0 || upper < 0.0 ? " to " : "-";
  return with_unit(low == high ? low : low + separator + high, prefix, unit);
}

}  // namespace gc
