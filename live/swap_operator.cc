#include "live/swap_operator.h"

#include <fmt/format.h>

#include <algorithm>

#include "core/model_error.h"
#include "live/live_names.h"

namespace gc::live {

std::string swap_operator(std::string_view operator_flag, std::string_view identity_operator) {
  if (!operator_flag.empty()) {
    const bool printable = std::all_of(operator_flag.begin(), operator_flag.end(), [](char c) {
      return c >= 0x20 && c < 0x7f && c != ';' && c != '=';
    });
    if (!printable || operator_flag.size() > kMaxOperatorNameChars ||
        operator_flag.find_first_not_of(' ') == std::string_view::npos) {
      throw InvalidInput("--operator",
                         fmt::format("'{}' is not an operator name: allowed 1 to {} printable "
                                     "characters, not only spaces, without ';' or '='",
                                     operator_flag, kMaxOperatorNameChars));
    }
    return std::string(operator_flag);
  }
  if (!identity_operator.empty()) return kOperatorIdentityPrefix + std::string(identity_operator);
  throw InvalidInput(
      "--operator",
      "required: give --operator NAME, the person putting the model in force, for the monitor's "
      "audit trail (under DDS Security an operator identity, GC_IDENTITY=operator-NAME, names "
      "them instead)");
}

std::string swap_user_data(std::string_view by, std::string_view source) {
  return fmt::format("by={};source={}", by, source);
}

}  // namespace gc::live
