#include "codec/coupling_file.h"

#include <set>
#include <string>


#include "codec/angle_units.h"
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
