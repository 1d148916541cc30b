#include "clients/dashboard/query_panel.h"

#include <optional>
#include <stdexcept>

#include <fmt/format.h>

#include "analysis/number_text.h"
#include "codec/angle_units.h"
#include "codec/result_json.h"
#include "codec/result_messages.h"
#include "core/model_error.h"
#include <google/protobuf/struct.pb.h>

namespace gc::dashboard {
namespace {

/// A request the browser got wrong: 400, naming the parameter.
struct BadParameter : std::runtime_error {
  using std::runtime_error::runtime_error;
};

double number(const std::map<std::string, std::string>& parameters, const std::string& name,
              std::optional<double> fallback) {
  const auto found = parameters.find(name);
  if (found == parameters.end() || found->second.empty()) {
    if (fallback) return *fallback;
    throw BadParameter(fmt::format("parameter {} is missing", name));
  }
  const std::optional<double> value = analysis::parse_double(found->second);
  if (!value) {
    throw BadParameter(fmt::format("parameter {} = \"{}\" is not a number", name, found->second));
  }
  return *value;
}

/// {"error": message}, the text escaped by protobuf's JSON printer.
std::string error_json(const std::string& message) {
  google::protobuf::Value text;
  text.set_string_value(message);
  return fmt::format("{{\"error\":{}}}", codec::to_compact_json(text));
}

}  // namespace

JsonAnswer QueryPanel::answer(const std::map<std::string, std::string>& parameters) const {
  try {
    const auto coupling = parameters.find("coupling");
    if (coupling == parameters.end() || coupling->second.empty()) {
      throw BadParameter("parameter coupling is missing: give a catalogue name");
    }
    const OperatingPoint point{
        .torque_nm = number(parameters, "torque_nm", std::nullopt),
        .misalignment_rad =
            codec::radians_from_degrees(number(parameters, "misalignment_deg", std::nullopt)),
        .direction_rad = codec::radians_from_degrees(number(parameters, "direction_deg", 0.0)),
        .friction_coefficient = number(parameters, "friction_coefficient", 0.0)};
    const std::string& name = coupling->second;
    const cli::JamAngleReport jam = calculator_.jam_angle(name);
    const cli::LoadCase load_case = calculator_.load_case(name, point, ContactOptions{});
    const std::string coupling_name = calculator_.coupling_name(name);
    return {200, fmt::format(
                     "{{\"jam_angle\":{},\"moments\":{},\"contact\":{}}}",
                     codec::to_compact_json(codec::to_message(coupling_name, jam.jam,
                                                              jam.crown_radius_m,
                                                              jam.crown_radius_derived)),
                     codec::to_compact_json(codec::to_message(coupling_name, point,
                                                              load_case.contact,
                                                              load_case.moments)),
                     codec::to_compact_json(
                         codec::to_message(coupling_name, point, load_case.contact)))};
  } catch (const BadParameter& error) {
    return {400, error_json(error.what())};
  } catch (const ModelError& error) {
    return {422, error_json(error.what())};
  } catch (const std::exception& error) {
    return {503, error_json(error.what())};
  }
}

}  // namespace gc::dashboard
