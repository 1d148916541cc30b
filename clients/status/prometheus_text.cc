#include "clients/status/prometheus_text.h"

#include <cmath>

#include <fmt/format.h>

namespace gc::status {
namespace {

/// Label values escape backslash, double quote and line feed (the format's only escapes).
std::string escaped_label_value(std::string_view value) {
  std::string out;
  out.reserve(value.size());
  for (const char c : value) {
    if (c == '\\') out += "\\\\";
    else if (c == '"') out += "\\\"";
    else if (c == '\n') out += "\\n";
    else out += c;
  }
  return out;
}

/// Go's float formatting as Prometheus parses it: NaN, +Inf, -Inf, else shortest round trip.
std::string value_text(double value) {
  if (std::isnan(value)) return "NaN";
  if (std::isinf(value)) return value > 0 ? "+Inf" : "-Inf";
  return fmt::format("{}", value);
}

}  // namespace

void PrometheusText::family(std::string_view name, std::string_view type,
                            std::string_view help) {
  text_ += fmt::format("# HELP {} {}\n# TYPE {} {}\n", name, help, name, type);
}

void PrometheusText::sample(std::string_view name, const Labels& labels, double value) {
  text_ += name;
  if (!labels.empty()) {
    text_ += '{';
    for (std::size_t i = 0; i < labels.size(); ++i) {
      if (i > 0) text_ += ',';
      text_ += fmt::format("{}=\"{}\"", labels[i].first, escaped_label_value(labels[i].second));
    }
    text_ += '}';
  }
  text_ += ' ';
  text_ += value_text(value);
  text_ += '\n';
}

}  // namespace gc::status
