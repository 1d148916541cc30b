#include "clients/dashboard/query_panel.h"

#include <optional>
#include <stdexcept>

#include <dds/dds.h>
#include <fmt/format.h>
#include <google/protobuf/struct.pb.h>

#include "analysis/input_names.h"
#include "analysis/number_text.h"
#include "codec/angle_units.h"
#include "codec/result_json.h"
#include "codec/result_messages.h"
#include "core/model_error.h"
#include "protocol/dds_error.h"
#include "protocol/reply_status.h"

namespace gc::dashboard {
namespace {

/// A request the browser got wrong: 400, naming the parameter.
struct BadParameter : std::runtime_error {
  BadParameter(const std::string& message, std::string name)
      : std::runtime_error(message), parameter(std::move(name)) {}
  std::string parameter;
};

double number(const std::map<std::string, std::string>& parameters, const std::string& name,
              std::optional<double> fallback) {
  const auto found = parameters.find(name);
  if (found == parameters.end() || found->second.empty()) {
    if (fallback) return *fallback;
    throw BadParameter(fmt::format("parameter {} is missing", name), name);
  }
  const std::optional<double> value = analysis::parse_double(found->second);
  if (!value) {
    throw BadParameter(fmt::format("parameter {} = \"{}\" is not a number", name, found->second),
                       name);
  }
  return *value;
}

/// {"error": message, "parameter": the query parameter it concerns (when known)}, the texts
/// escaped by protobuf's JSON printer. The page puts the value as typed, in its input's unit,
/// before the message (as the CLI puts the flag and its value).
std::string error_json(const std::string& message, std::string_view parameter = "") {
  google::protobuf::Struct body;
  (*body.mutable_fields())["error"].set_string_value(message);
  if (!parameter.empty()) {
    (*body.mutable_fields())["parameter"].set_string_value(std::string(parameter));
  }
  return codec::to_compact_json(body);
}

bool refused_by_security(const protocol::DdsError& error) {
  return error.code() == DDS_RETCODE_NOT_ALLOWED_BY_SECURITY;
}

}  // namespace

QueryPanel::QueryPanel(client::ClientOptions options) {
  try {
    calculator_ = std::make_unique<calculators::RemoteCalculator>(options);
  } catch (const protocol::DdsError& error) {
    if (!refused_by_security(error)) throw;
    refusal_ = refusal_message(error.what());
  }
}

std::string QueryPanel::refusal_message(const std::string& dds_error) {
  return "the query panel may not ask the service: DDS Security does not let this dashboard's "
         "identity send requests or read replies (a dashboard-* identity of "
         "deploy/security/make-security.sh may only read the status and the live test cells). "
         "To use the panel, run gearcoupling-dashboard under a console identity "
         "(make-security.sh --console NAME; CYCLONEDDS_URI naming console-NAME/security.xml) "
         "with --client-id-prefix (or GC_CLIENT_ID_PREFIX) set to its client_id_prefix file "
         "(docs/security.md). DDS said: " + dds_error;
}

JsonAnswer QueryPanel::answer(const std::map<std::string, std::string>& parameters) const {
  JsonAnswer answer = answer_uncounted(parameters);
  // 400 and 422: the user's input, refused; 403 and 503: the panel or the service failed.
  (answer.status == 200                            ? answered_
   : answer.status == 400 || answer.status == 422 ? refused_
                                                   : failed_) += 1;
  return answer;
}

QueryCounts QueryPanel::counts() const { return {answered_, refused_, failed_}; }

JsonAnswer QueryPanel::answer_uncounted(const std::map<std::string, std::string>& parameters) const {
  if (calculator_ == nullptr) return {403, error_json(refusal_)};
  try {
    return compute(parameters);
  } catch (const protocol::DdsError& error) {
    if (refused_by_security(error)) return {403, error_json(refusal_message(error.what()))};
    return {503, error_json(error.what())};
  }
}

JsonAnswer QueryPanel::compute(const std::map<std::string, std::string>& parameters) const {
  try {
    const auto coupling = parameters.find("coupling");
    if (coupling == parameters.end() || coupling->second.empty()) {
      throw BadParameter("parameter coupling is missing: give a catalogue name", "coupling");
    }
    const OperatingPoint point{
        .torque_nm = number(parameters, "torque_nm", std::nullopt),
        .misalignment_rad =
            codec::radians_from_degrees(number(parameters, "misalignment_deg", std::nullopt)),
        .direction_rad = codec::radians_from_degrees(number(parameters, "direction_deg", 0.0)),
        .friction_coefficient = number(parameters, "friction_coefficient", 0.0)};
    const std::string& name = coupling->second;
    const calculators::JamAngleReport jam = calculator_->jam_angle(name);
    const analysis::LoadCase load_case = calculator_->load_case(name, point, ContactOptions{});
    const std::string coupling_name = calculator_->coupling_name(name);
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
    return {400, error_json(error.what(), error.parameter)};
  } catch (const InvalidInput& error) {
    return {422, error_json(error.what(), analysis::query_parameter_for_field(error.field()))};
  } catch (const protocol::ServiceError& error) {
    // An unknown coupling is the user's input; a deadline exceeded or an internal error is not.
    if (!protocol::refuses_input(error.status())) return {503, error_json(error.what())};
    return {422, error_json(error.what(), analysis::query_parameter_for_field(error.field()))};
  } catch (const ModelError& error) {
    return {422, error_json(error.what())};
  } catch (const protocol::DdsError&) {
    throw;  // answer() tells a security refusal from the rest
  } catch (const std::exception& error) {
    return {503, error_json(error.what())};
  }
}

}  // namespace gc::dashboard
