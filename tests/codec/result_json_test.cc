#include "codec/result_json.h"

#include <cmath>
#include <set>
#include <string>

#include <google/protobuf/util/json_util.h>
#include <google/protobuf/util/message_differencer.h>
#include <gtest/gtest.h>

#include "codec/coupling_catalog.h"
#include "codec/count_field.h"
#include "codec/result_messages.h"
#include "core/coupling_geometry.h"
#include "core/model_error.h"
#include "idl/diagnosis.pb.h"
#include "idl/validation.pb.h"

namespace gc::codec {
namespace {

namespace pb = google::protobuf;

const CouplingGeometry& upwind() {
  static const CouplingGeometry geometry =
      load_coupling_geometry(std::string(GC_BUNDLED_CATALOG_DIR) + "/nrel_upwind.textproto");
  return geometry;
}

// The benchmark's load case: 1.5 MN·m, 0.4 deg, mu 0.1.
OperatingPoint nominal_point() {
  return {.torque_nm = 1.5e6, .misalignment_rad = 0.4 * M_PI / 180.0, .direction_rad = 0.3,
          .friction_coefficient = 0.1};
}

template <typename Message>
Message parse_back(const std::string& json) {
  Message parsed;
  const auto status = pb::util::JsonStringToMessage(json, &parsed);
  EXPECT_TRUE(status.ok()) << status.ToString();
  return parsed;
}

// Counts of validate and diagnose are numbers in JSON, as in the calculation JSON: protobuf
// writes 64-bit integers as strings, so the schemas hold them in 32 bits.
TEST(ResultJson, ValidationAndDiagnosisCountsAreNumbers) {
  gearcoupling::v1::DiagnosisResult diagnosis;
  diagnosis.set_recording_rows(1000);
  diagnosis.set_outlier_rows(3);
  diagnosis.add_rounds()->add_signature()->add_bins()->set_count(17);
  const std::string diagnosis_json = to_json(diagnosis);
  EXPECT_NE(diagnosis_json.find("\"recording_rows\": 1000,"), std::string::npos) << diagnosis_json;
  EXPECT_NE(diagnosis_json.find("\"outlier_rows\": 3"), std::string::npos) << diagnosis_json;
  EXPECT_NE(diagnosis_json.find("\"count\": 17,"), std::string::npos) << diagnosis_json;
  gearcoupling::v1::ValidationResult validation;
  validation.set_recording_rows(4000000000u);
  validation.add_row_problems()->set_line(12);
  const std::string validation_json = to_json(validation);
  EXPECT_NE(validation_json.find("\"recording_rows\": 4000000000,"), std::string::npos) << validation_json;
  EXPECT_NE(validation_json.find("\"line\": 12,"), std::string::npos) << validation_json;
}

TEST(CountField, RefusesACountBeyondUint32RatherThanWrap) {
  EXPECT_EQ(count_field(4294967295u, "recording_rows"), 4294967295u);
  try {
    count_field(4294967296u, "recording_rows");
    FAIL();
  } catch (const InvalidInput& error) {
    EXPECT_EQ(error.field(), "recording_rows");
  }
}

TEST(ResultJson, ToothContactParsesBackBitForBit) {
  const OperatingPoint point = nominal_point();
  const ToothContact contact = tooth_contact(upwind(), point);
  const v1::ToothContactResult message = to_message(upwind().name(), point, contact);
  const auto parsed = parse_back<v1::ToothContactResult>(to_json(message));
  EXPECT_TRUE(pb::util::MessageDifferencer::Equals(message, parsed));
  ASSERT_EQ(parsed.teeth_size(), 100);
  EXPECT_EQ(parsed.teeth(7).load_n(), contact.teeth[7].load_n);  // exact: doubles round-trip
  EXPECT_EQ(parsed.teeth(0).slice_loads_n_size(), 21);           // N_s = 20 slices -> 21 loads
  EXPECT_EQ(parsed.max_stress().contact_stress_pa(), contact.max_stress.contact_stress_pa);
}

TEST(ResultJson, PrintsUnitNamedFieldsAndZeroes) {
  const OperatingPoint point = nominal_point();
  const ToothContact contact = tooth_contact(upwind(), point);
  const InducedMoments moments = induced_moments(upwind(), point, contact);
  const std::string json = to_json(to_message(upwind().name(), point, contact, moments));
  for (const char* key : {"\"moment_y_nm\"", "\"sensor_moment_z_nm\"", "\"direction_deg\"",
                          "\"max_tooth_load_n\"", "\"torque_nm\"", "\"misalignment_deg\""}) {
    EXPECT_NE(json.find(key), std::string::npos) << key;
  }
  EXPECT_EQ(json.find("momentYNm"), std::string::npos);  // proto names, not lowerCamelCase
  const auto parsed = parse_back<v1::InducedMomentsResult>(json);
  EXPECT_EQ(parsed.moment_z_nm(), moments.moment_z_nm);
  EXPECT_NEAR(parsed.operating_point().misalignment_deg(), 0.4, 1e-12);
}

TEST(ResultJson, AlignedCouplingPrintsNoInfinityOrNan) {
  OperatingPoint point = nominal_point();
  point.misalignment_rad = 0.0;
  const ToothContact contact = tooth_contact(upwind(), point);
  ASSERT_FALSE(std::isfinite(contact.load_sharing.ze_over_zo));
  const std::string json = to_json(to_message(upwind().name(), point, contact));
  EXPECT_EQ(json.find("Infinity"), std::string::npos);
  EXPECT_EQ(json.find("NaN"), std::string::npos);
  EXPECT_NE(json.find("\"edge_loaded\": false"), std::string::npos);  // zero values printed
}

TEST(ResultJson, JamAngleRestoringTorqueAndFrictionParseBack) {
  const auto jam = to_message(upwind().name(), upwind().jam_angle(), upwind().crown_radius_m(),
                              upwind().crown_radius_derived());
  const auto jam_back = parse_back<v1::JamAngleResult>(to_json(jam));
  EXPECT_TRUE(pb::util::MessageDifferencer::Equals(jam, jam_back));
  EXPECT_NEAR(jam_back.angle_deg(), jam_back.angle_rad() * 180.0 / M_PI, 1e-12);

  const auto torque = to_message(upwind().name(), restoring_torque(upwind()));
  EXPECT_TRUE(pb::util::MessageDifferencer::Equals(
      torque, parse_back<v1::RestoringTorqueResult>(to_json(torque))));

  const FrictionMeasurement measurement{1.5e6, 0.005, 0.2, -50000.0, 120000.0};
  const auto friction =
      to_message(upwind().name(), measurement, estimate_friction(upwind(), measurement));
  EXPECT_TRUE(pb::util::MessageDifferencer::Equals(
      friction, parse_back<v1::FrictionEstimateResult>(to_json(friction))));
}

// Every field of results.proto says its unit, or is dimensionless by nature.
void expect_unit_names(const pb::Descriptor* descriptor, std::set<std::string>& seen) {
  static const std::set<std::string> dimensionless = {
      "coupling", "q", "ze_over_zo", "iterations", "friction_coefficient", "index",
      "teeth_in_contact", "max_load_tooth", "edge_loaded", "slice_weights",
      "contact_safety_factor", "bending_safety_factor", "governing", "crown_radius_derived",
      "root_contact", "teeth_summed"};
  static const std::vector<std::string> units = {"_nm", "_n", "_m", "_pa", "_deg", "_rad"};
  if (!seen.insert(descriptor->full_name()).second) return;
  for (int i = 0; i < descriptor->field_count(); ++i) {
    const pb::FieldDescriptor* field = descriptor->field(i);
    if (field->type() == pb::FieldDescriptor::TYPE_MESSAGE) {
      expect_unit_names(field->message_type(), seen);
      continue;
    }
    const std::string& name = field->name();
    const bool has_unit = std::any_of(units.begin(), units.end(), [&](const std::string& u) {
      return name.size() > u.size() && name.compare(name.size() - u.size(), u.size(), u) == 0;
    });
    EXPECT_TRUE(has_unit || dimensionless.contains(name)) << descriptor->name() << "." << name;
  }
}

TEST(ResultJson, EveryResultFieldNameCarriesItsUnit) {
  std::set<std::string> seen;
  for (const pb::Descriptor* d :
       {v1::ToothContactResult::descriptor(), v1::JamAngleResult::descriptor(),
        v1::InducedMomentsResult::descriptor(), v1::RestoringTorqueResult::descriptor(),
        v1::FrictionEstimateResult::descriptor()}) {
    expect_unit_names(d, seen);
  }
  EXPECT_GE(seen.size(), 9u);
}

}  // namespace
}  // namespace gc::codec
