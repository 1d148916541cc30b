#include "codec/coupling_file.h"

#include <cmath>
#include <set>
#include <string>

#include <cstdio>

#include "codec/angle_units.h"
#include "codec/file_input_error.h"
#include "codec/text_format.h"
#include "core/model_error.h"
#include "idl/coupling.pb.h"

namespace gc::codec {
namespace {

namespace pb = google::protobuf;

// Fields idl/coupling.proto marks "optional use"; every other field is required. The field
// names are the schema's, so a renamed field fails the catalogue tests rather than passing here.
const std::set<std::string, std::less<>>& optional_fields() {
  static const std::set<std::string, std::less<>> fields = {
      "description", "crown_radius_m", "sleeve_root_diameter_m"};
  return fields;
}

// Every field of `message` (and of its set sub-messages) that is neither set nor optional use.
void require_fields(const pb::Message& message, const std::string& path,
                    std::string_view source) {
  const pb::Descriptor* descriptor = message.GetDescriptor();
  const pb::Reflection* reflection = message.GetReflection();
  for (int i = 0; i < descriptor->field_count(); ++i) {
    const pb::FieldDescriptor* field = descriptor->field(i);
    const std::string field_path = path + "." + field->name();
    if (!reflection->HasField(message, field)) {
      if (optional_fields().contains(field->name())) continue;
      throw InvalidInput(field_path, "required field missing in " + std::string(source));
    }
    if (field->type() == pb::FieldDescriptor::TYPE_MESSAGE) {
      require_fields(reflection->GetMessage(message, field), field_path, source);
    }
  }
}

// The checks whose core wording would mislead a reader of the file, made first in the file's
// terms. The core (core/coupling_geometry.cc) checks angles in radians under _rad names; the
// file writes degrees under _deg names. Its consistency checks blame one field when either may
// be the typo. The bounds are the core's, converted, so the codec accepts exactly what the
// core accepts (tests/codec/coupling_file_test.cc holds both at the edges).
struct DegreeBounds {
  const char* field;
  double lo_rad, hi_rad;   // core/coupling_geometry.cc validate_definition
};
constexpr DegreeBounds kDegreeBounds[] = {
    {"pressure_angle_deg", 0.0873, 0.7854},
    {"design_misalignment_deg", 0.0, 0.1745},
    {"tilt_deg", -1.5708, 1.5708},
};
// Table 1's diameters are rounded to 0.01 mm: the core allows this relative slack.
constexpr double kConsistency = 5e-3;

// A bound in degrees for a message, rounded inwards to 4 significant digits, so that every
// value within the printed range is accepted.
std::string degrees_inward(double radians, bool lower) {
  const double degrees = degrees_from_radians(radians);
  if (degrees == 0.0) return "0";
  const double step = std::pow(10.0, std::floor(std::log10(std::abs(degrees))) - 3);
  const double rounded = (lower ? std::ceil(degrees / step) : std::floor(degrees / step)) * step;
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", rounded);
  return text;
}

void check_in_file_units(const gearcoupling::v1::CouplingDefinition& m, std::string_view source) {
  const pb::Reflection* reflection = m.GetReflection();
  for (const DegreeBounds& bounds : kDegreeBounds) {
    const double degrees =
        reflection->GetDouble(m, m.GetDescriptor()->FindFieldByName(bounds.field));
    const double radians = radians_from_degrees(degrees);
    if (!std::isfinite(degrees) || radians < bounds.lo_rad || radians > bounds.hi_rad) {
      const std::string field = std::string("coupling.") + bounds.field;
      throw FileInputError(field, field + " = " + format_precise(degrees) +
                                      " is out of range: allowed [" +
                                      degrees_inward(bounds.lo_rad, true) + ", " +
                                      degrees_inward(bounds.hi_rad, false) + "] deg (in " +
                                      std::string(source) + ")");
    }
  }
  if (!std::isfinite(m.profile_relief_start_roll_deg())) {
    throw FileInputError("coupling.profile_relief_start_roll_deg",
                         "coupling.profile_relief_start_roll_deg = " +
                             format_precise(m.profile_relief_start_roll_deg()) +
                             " is not a finite number of degrees (in " + std::string(source) + ")");
  }
  // Only once both sides are numbers the core would take one by one.
  const auto positive = [](double x) { return std::isfinite(x) && x > 0.0; };
  if (m.teeth() >= 8 && positive(m.module_m()) && positive(m.pitch_diameter_m())) {
    const double expected = m.teeth() * m.module_m();
    if (std::abs(m.pitch_diameter_m() - expected) > kConsistency * expected) {
      throw FileInputError(
          "coupling.pitch_diameter_m",
          "coupling.pitch_diameter_m = " + format_precise(m.pitch_diameter_m()) +
              " m and coupling.teeth * coupling.module_m = " + std::to_string(m.teeth()) + " * " +
              format_precise(m.module_m()) + " m = " + format_number(expected) +
              " m disagree: the pitch diameter is N * module within 0.5 %; one of the three is "
              "wrong (in " + std::string(source) + ")");
    }
  }
  const double pressure_angle = radians_from_degrees(m.pressure_angle_deg());
  if (positive(m.pitch_diameter_m()) && positive(m.base_diameter_m())) {
    const double expected = m.pitch_diameter_m() * std::cos(pressure_angle);
    if (std::abs(m.base_diameter_m() - expected) > kConsistency * expected) {
      throw FileInputError(
          "coupling.base_diameter_m",
          "coupling.base_diameter_m = " + format_precise(m.base_diameter_m()) +
              " m and coupling.pitch_diameter_m * cos(coupling.pressure_angle_deg) = " +
              format_precise(m.pitch_diameter_m()) + " m * cos(" +
              format_precise(m.pressure_angle_deg()) + " deg) = " + format_number(expected) +
              " m disagree: the base diameter is D cos(phi) within 0.5 %; one of the three is "
              "wrong (in " + std::string(source) + ")");
    }
  }
}

CouplingDefinition from_message(const gearcoupling::v1::CouplingDefinition& m) {
  CouplingDefinition d;
  d.name = m.name();
  d.teeth = m.teeth();
  d.module_m = m.module_m();
  d.pressure_angle_rad = radians_from_degrees(m.pressure_angle_deg());
  d.pitch_diameter_m = m.pitch_diameter_m();
  d.base_diameter_m = m.base_diameter_m();
  d.outer_diameter_m = m.outer_diameter_m();
  d.root_diameter_m = m.root_diameter_m();
  d.center_distance_m = m.center_distance_m();
  d.backlash_m = m.backlash_m();
  d.tooth_thickness_m = m.tooth_thickness_m();
  d.tool_tip_radius_m = m.tool_tip_radius_m();
  d.facewidth_m = m.facewidth_m();
  d.lead_modification_m = m.lead_modification_m();
  d.profile_tip_relief_m = m.profile_tip_relief_m();
  d.profile_relief_start_roll_rad = radians_from_degrees(m.profile_relief_start_roll_deg());
  if (m.has_crown_radius_m()) d.crown_radius_m = m.crown_radius_m();
  d.form_factor_hub = m.form_factor_hub();
  d.form_factor_sleeve = m.form_factor_sleeve();
  d.youngs_modulus_pa = m.youngs_modulus_pa();
  d.poisson_ratio = m.poisson_ratio();
  d.design_misalignment_rad = radians_from_degrees(m.design_misalignment_deg());
  d.coupling_weight_n = m.coupling_weight_n();
  d.shaft_weight_per_length_n_per_m = m.shaft_weight_per_length_n_per_m();
  d.shaft_length_m = m.shaft_length_m();
  d.tilt_rad = radians_from_degrees(m.tilt_deg());
  if (m.has_sleeve_root_diameter_m()) d.sleeve_root_diameter_m = m.sleeve_root_diameter_m();
  d.allowables.contact_stress_pa = m.allowables().contact_stress_pa();
  d.allowables.bending_stress_pa = m.allowables().bending_stress_pa();
  return d;
}

}  // namespace

CouplingDefinition parse_coupling_text(std::string_view text, std::string_view source_name) {
  gearcoupling::v1::CouplingDefinition message;
  parse_text_format(text, source_name, "coupling", message);
  require_fields(message, "coupling", source_name);
  if (message.name().empty()) {
    throw InvalidInput("coupling.name", "must not be empty in " + std::string(source_name));
  }
  check_in_file_units(message, source_name);
  return from_message(message);
}

CouplingDefinition parse_coupling_json(std::string_view json, std::string_view source_name) {
  gearcoupling::v1::CouplingDefinition message;
  return parse_coupling_text(text_format_from_json(json, source_name, "coupling", message),
                             source_name);
}

CouplingDefinition load_coupling_file(const std::filesystem::path& path) {
  return parse_coupling_text(read_text_file(path, "coupling"), path.filename().string());
}

}  // namespace gc::codec
