#include "clients/status/parameter_display.h"

#include <fmt/format.h>

#include "core/engineering_text.h"

namespace gc::status {
namespace {

/// A temperature coefficient per K reads as per °C (the same step); the rest as given.
std::string display_unit(const std::string& unit) {
  if (unit.size() >= 2 && unit.ends_with("/K")) return unit.substr(0, unit.size() - 1) + "°C";
  return unit;
}

}  // namespace

std::string parameter_display(const ::gearcoupling::v1::ProposedParameterRecord& p) {
  const std::string unit = display_unit(p.unit());
  std::string text = fmt::format("{}.{} = {}", p.effect(), p.name(), engineering_text(p.value(), unit));
  if (p.held()) return text + " (held)";
  text += " ± " + engineering_text(p.standard_error(), unit, p.value());
  return p.plausible() ? text : text + " (implausible)";
}

}  // namespace gc::status
