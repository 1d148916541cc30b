#include "analysis/effect_spec.h"

#include <fmt/format.h>

#include "analysis/format_error.h"
#include "analysis/number_text.h"
#include "codec/nearest_name.h"
#include "core/effects/effect_registry.h"
#include "core/model_error.h"

namespace gc::analysis {

std::shared_ptr<const Effect> parse_effect_spec(std::string_view spec) {
  const std::size_t equals = spec.find('=');
  const std::string name(trim(spec.substr(0, equals)));
  if (name.empty()) throw FormatError(fmt::format("--add '{}': expected EFFECT[=parameter=value,...]", spec));
  ParameterValues values;
  std::string_view rest = equals == std::string_view::npos ? std::string_view() : spec.substr(equals + 1);
  while (!rest.empty()) {
    const std::size_t comma = rest.find(',');
    const std::string_view item = rest.substr(0, comma);
    rest = comma == std::string_view::npos ? std::string_view() : rest.substr(comma + 1);
    const std::size_t eq = item.find('=');
    const auto value = eq == std::string_view::npos ? std::nullopt : parse_double(item.substr(eq + 1));
    if (!value) {
      throw FormatError(fmt::format("--add '{}': '{}' is not parameter=number (SI units)", spec, item));
    }
    values[std::string(trim(item.substr(0, eq)))] = *value;
  }
  try {
    return make_effect(name, values);
  } catch (const InvalidInput& error) {
    // A misspelt effect ("--add eccentricty") gets the library's nearest name (issue 39).
    if (error.field() != "effects." + name) throw;
    const std::string what = error.what();
    throw InvalidInput(error.field(), what.substr(error.field().size() + 2) +
                                          codec::did_you_mean_effect(name));
  }
}

std::string effect_spec_text(const Effect& effect) {
  std::string text = effect.name();
  const std::vector<ParameterSpec>& parameters = effect.info().parameters;
  for (std::size_t i = 0; i < parameters.size(); ++i) {
    // Six significant digits: what a fit determines and enough to reproduce a validation; the
    // shortest round trip (17) differs between CPUs in its last digits.
    text += (i == 0 ? "=" : ",") + parameters[i].name + "=" + fmt::format("{:.6g}", effect.values()[i]);
  }
  return text;
}

}  // namespace gc::analysis
