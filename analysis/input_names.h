// The core names a bad input by its field ("operating_point.misalignment_rad"); the user wrote
// a flag ("--misalignment-deg") or a CSV column ("misalignment_deg"). One table maps the one to
// the others so that every error names what the user typed, with the value as typed.
#pragma once

#include <string>
#include <string_view>

#include "core/model_error.h"

namespace gc::analysis {

/// The flag (without "--") for a core field, or "" when no flag sets it.
std::string_view flag_for_field(std::string_view field);

/// The batch CSV column for a core field, or "" when no column sets it.
std::string_view column_for_field(std::string_view field);

/// The dashboard's /api/query parameter for a core field ("torque_nm", "misalignment_deg",
/// "direction_deg", "friction_coefficient", "coupling"), or "" when none sets it.
std::string_view query_parameter_for_field(std::string_view field);

/// "<user_name> <user_value>: <the core's message>", or just the core's message when
/// `user_name` is empty. The core's message carries the field, value in SI and allowed range.
std::string describe_input_error(const InvalidInput& error, std::string_view user_name,
                                 std::string_view user_value);

/// Said where a negative torque is refused: "; the model takes the torque as a magnitude
/// (T > 0): <remedy>" (for a dyno that logs the drive torque negative: --negate torque for a
/// recording, the magnitude for a flag or a batch column).
std::string negative_torque_hint(std::string_view remedy);

/// Whether `error` refuses a negative torque (operating_point.torque_nm = -...).
bool refuses_negative_torque(const InvalidInput& error);
bool refuses_negative_torque(std::string_view field, std::string_view message);

}  // namespace gc::analysis
