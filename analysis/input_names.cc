#include "analysis/input_names.h"

#include <array>

namespace gc::analysis {
namespace {

struct InputName {
  std::string_view field;   // as the core names it
  std::string_view flag;    // without "--"
  std::string_view column;  // batch CSV header
  std::string_view query = "";  // the dashboard's /api/query parameter
};

constexpr std::array<InputName, 12> kInputNames = {{
    {"operating_point.torque_nm", "torque-nm", "torque_nm", "torque_nm"},
    {"operating_point.misalignment_rad", "misalignment-deg", "misalignment_deg", "misalignment_deg"},
    {"operating_point.direction_rad", "direction-deg", "direction_deg", "direction_deg"},
    {"operating_point.friction_coefficient", "mu", "mu", "friction_coefficient"},
    {"options.slices", "slices", ""},
    {"options.load_sharing.tolerance", "tolerance", ""},
    {"options.load_sharing.max_iterations", "max-iterations", ""},
    {"measurement.torque_nm", "torque-nm", ""},
    {"measurement.misalignment_rad", "misalignment-deg", ""},
    {"measurement.direction_rad", "direction-deg", ""},
    {"measurement.sensor_moment_y_nm", "msy-nm", ""},
    {"measurement.sensor_moment_z_nm", "msz-nm", ""},
}};

const InputName* find(std::string_view field) {
  for (const InputName& name : kInputNames) {
    if (name.field == field) return &name;
  }
  return nullptr;
}

// Every "coupling..." field comes from the coupling the user named.
bool is_coupling_field(std::string_view field) {
  return field == "coupling" || field.starts_with("coupling.") || field == "catalog";
}

}  // namespace

std::string_view flag_for_field(std::string_view field) {
  if (is_coupling_field(field)) return field == "catalog" ? "catalogue" : "coupling";
  const InputName* name = find(field);
  return name ? name->flag : "";
}

std::string_view column_for_field(std::string_view field) {
  if (is_coupling_field(field)) return "coupling";
  const InputName* name = find(field);
  return name ? name->column : "";
}

std::string_view query_parameter_for_field(std::string_view field) {
  if (is_coupling_field(field)) return "coupling";
  const InputName* name = find(field);
  return name ? name->query : "";
}

std::string describe_input_error(const InvalidInput& error, std::string_view user_name,
                                 std::string_view user_value) {
  if (user_name.empty()) return error.what();
  return std::string(user_name) + " " + std::string(user_value) + ": " + error.what();
}

std::string negative_torque_hint(std::string_view remedy) {
  return "; the model takes the torque as a magnitude (T > 0): " + std::string(remedy);
}

bool refuses_negative_torque(std::string_view field, std::string_view message) {
  return field == "operating_point.torque_nm" &&
         message.find("operating_point.torque_nm = -") != std::string_view::npos;
}

bool refuses_negative_torque(const InvalidInput& error) {
  return refuses_negative_torque(error.field(), error.what());
}

}  // namespace gc::analysis
