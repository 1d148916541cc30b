#include "codec/coupling_file.h"

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "core/coupling_geometry.h"
#include "core/model_error.h"

namespace gc::codec {
namespace {

std::string bundled_text(const std::string& name) {
  std::ifstream in(std::string(GC_BUNDLED_CATALOG_DIR) + "/" + name + ".textproto");
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The bundled upwind text with the line holding `field` removed.
std::string without_line_of(const std::string& text, const std::string& field) {
  std::istringstream in(text);
  std::string out, line;
  while (std::getline(in, line)) {
    if (line.rfind(field, 0) != 0) out += line + "\n";
  }
  return out;
}

// Runs `parse` and returns the InvalidInput it throws; fails the test if it throws nothing.
template <typename Parse>
InvalidInput error_of(Parse parse) {
  try {
    parse();
  } catch (const InvalidInput& error) {
    return error;
  }
  ADD_FAILURE() << "no InvalidInput thrown";
  return InvalidInput("none", "none");
}

TEST(CouplingFile, LoadsBundledUpwindWithTable1ValuesInSi) {
  const CouplingDefinition d =
      load_coupling_file(std::string(GC_BUNDLED_CATALOG_DIR) + "/nrel_upwind.textproto");
  EXPECT_EQ(d.name, "nrel_upwind");
  EXPECT_EQ(d.teeth, 100);
  EXPECT_DOUBLE_EQ(d.pitch_diameter_m, 1.016);
  EXPECT_DOUBLE_EQ(d.backlash_m, 0.00064);
  EXPECT_DOUBLE_EQ(d.allowables.contact_stress_pa, 1.1e9);
  EXPECT_FALSE(d.crown_radius_m.has_value());  // optional use, absent in the file
}

TEST(CouplingFile, LoadsBundledDownwind) {
  const CouplingDefinition d =
      load_coupling_file(std::string(GC_BUNDLED_CATALOG_DIR) + "/nrel_downwind.textproto");
  EXPECT_EQ(d.name, "nrel_downwind");
  EXPECT_GT(d.teeth, 0);
}

TEST(CouplingFile, ConvertsDegreesToRadians) {
  const CouplingDefinition d = parse_coupling_text(bundled_text("nrel_upwind"), "up");
  EXPECT_NEAR(d.pressure_angle_rad, 20.0 * M_PI / 180.0, 1e-15);          // file: 20.0 deg
  EXPECT_NEAR(d.profile_relief_start_roll_rad, 23.6 * M_PI / 180.0, 1e-15);  // file: 23.6 deg
  const std::string tilted =
      without_line_of(bundled_text("nrel_upwind"), "tilt_deg") + "tilt_deg: 5\n";
  EXPECT_NEAR(parse_coupling_text(tilted, "t").tilt_rad, 5.0 * M_PI / 180.0, 1e-15);
}

TEST(CouplingFile, MissingRequiredFieldIsNamedWithTheFile) {
  const std::string text = without_line_of(bundled_text("nrel_upwind"), "backlash_m");
  const InvalidInput error =
      error_of([&] { parse_coupling_text(text, "nrel_upwind.textproto"); });
  EXPECT_EQ(error.field(), "coupling.backlash_m");
  EXPECT_STREQ(error.what(),
               "coupling.backlash_m: required field missing in nrel_upwind.textproto");
}

TEST(CouplingFile, MissingNestedAllowableIsNamedWithItsPath) {
  std::string text = bundled_text("nrel_upwind");
  text = without_line_of(text, "  bending_stress_pa");
  const InvalidInput error = error_of([&] { parse_coupling_text(text, "f.textproto"); });
  EXPECT_EQ(error.field(), "coupling.allowables.bending_stress_pa");
}

TEST(CouplingFile, OptionalUseFieldsMayBeAbsentOrGiven) {
  const std::string text = bundled_text("nrel_upwind") + "crown_radius_m: 1.64\n";
  const CouplingDefinition d = parse_coupling_text(text, "f");
  ASSERT_TRUE(d.crown_radius_m.has_value());
  EXPECT_DOUBLE_EQ(*d.crown_radius_m, 1.64);
}

TEST(CouplingFile, UnknownFieldIsNamedWithLineAndColumn) {
  // Line 1 of the text; protobuf reports the column just past the name (the colon, column 14).
  const std::string text = "  backlash_mm: 0.1\n" + bundled_text("nrel_upwind");
  const InvalidInput error = error_of([&] { parse_coupling_text(text, "bad.textproto"); });
  EXPECT_EQ(error.field(), "coupling.backlash_mm");
  const std::string what = error.what();
  EXPECT_NE(what.find("bad.textproto:1:14:"), std::string::npos) << what;
  EXPECT_NE(what.find("backlash_mm"), std::string::npos) << what;
}

// Issue 39: a typo gets the field it was meant for, nested fields too; a name far from every
// field gets no guess.
TEST(CouplingFile, MisspeltFieldSuggestsTheNearestFieldOfItsMessage) {
  const auto what_of = [](const std::string& text) {
    return std::string(error_of([&] { parse_coupling_text(text, "typo.textproto"); }).what());
  };
  const std::string upwind = bundled_text("nrel_upwind");
  std::string module_typo = upwind;
  module_typo.replace(module_typo.find("module_m:"), 9, "modul_m:");
  EXPECT_NE(what_of(module_typo).find("no field named \"modul_m\"; did you mean 'module_m'?"),
            std::string::npos) << what_of(module_typo);
  std::string nested_typo = upwind;
  nested_typo.replace(nested_typo.find("contact_stress_pa:"), 18, "contact_stres_pa:");
  EXPECT_NE(what_of(nested_typo).find("did you mean 'contact_stress_pa'?"), std::string::npos)
      << what_of(nested_typo);
  EXPECT_EQ(what_of("  colour: 3\n" + upwind).find("did you mean"), std::string::npos);
}

TEST(CouplingFile, SyntaxErrorNamesLineAndColumn) {
  const std::string text = "name: \"x\"\nteeth 100\n";  // line 2 lacks its colon
  const InvalidInput error = error_of([&] { parse_coupling_text(text, "syntax.textproto"); });
  const std::string what = error.what();
  EXPECT_NE(what.find("syntax.textproto:2:"), std::string::npos) << what;
}

TEST(CouplingFile, WrongValueTypeIsAnError) {
  const std::string text =
      without_line_of(bundled_text("nrel_upwind"), "teeth") + "teeth: \"many\"\n";
  const InvalidInput error = error_of([&] { parse_coupling_text(text, "type.textproto"); });
  EXPECT_NE(std::string(error.what()).find("type.textproto:"), std::string::npos);
}

// The schema's comments say which fields are "optional use"; every other field must be
// required by the loader. Removing each top-level field of the bundled file in turn checks
// that the loader and idl/coupling.proto agree.
TEST(CouplingFile, RequiresExactlyTheFieldsTheSchemaDoesNotMarkOptionalUse) {
  std::ifstream schema(GC_COUPLING_PROTO);
  ASSERT_TRUE(schema) << GC_COUPLING_PROTO;
  const std::string upwind = bundled_text("nrel_upwind");
  std::string line;
  bool in_definition = false;
  int checked = 0;
  while (std::getline(schema, line)) {
    if (line.rfind("message CouplingDefinition", 0) == 0) in_definition = true;
    if (!in_definition || line.find("  optional ") != 0) continue;
    std::istringstream words(line);
    std::string optional_word, type, name;
    words >> optional_word >> type >> name;
    const bool optional_use = line.find("optional use") != std::string::npos;
    const std::string text = without_line_of(upwind, name + ":") + "\n";
    if (text.size() == upwind.size() + 1) continue;  // the bundled file does not set it
    if (text.find(name + " {") != std::string::npos) continue;  // a message: checked below
    bool threw = false;
    try {
      parse_coupling_text(text, "f");
    } catch (const InvalidInput& error) {
      threw = true;
      EXPECT_EQ(error.field(), "coupling." + name);
    }
    EXPECT_EQ(threw, !optional_use) << name;
    ++checked;
  }
  EXPECT_GE(checked, 25);  // teeth ... tilt_deg and name, description
}

TEST(CouplingFile, UnreadableFileIsAnError) {
  EXPECT_THROW(load_coupling_file("/nonexistent/none.textproto"), InvalidInput);
}

// The whole message of the InvalidInput `parse` throws (caught by reference: the codec's
// FileInputError writes its own), or "" when it throws none.
template <typename Parse>
std::string message_of(Parse parse) {
  try {
    parse();
  } catch (const InvalidInput& error) {
    return error.what();
  }
  return "";
}

// The bundled upwind text with the line that starts with `field` replaced by `field: value`.
std::string upwind_with(const std::string& field, const std::string& value) {
  return without_line_of(bundled_text("nrel_upwind"), field + ":") + field + ": " + value + "\n";
}

TEST(CouplingFile, MissingFileSaysWhyWithTheOperatingSystemsReason) {
  const std::string message = message_of([] { load_coupling_file("/nonexistent/none.textproto"); });
  EXPECT_EQ(message, "coupling: cannot read coupling file /nonexistent/none.textproto: "
                     "No such file or directory");
  EXPECT_NE(message_of([] { load_coupling_file("/"); }).find("Is a directory"), std::string::npos);
}

TEST(CouplingFile, ModuleTypoNamesEveryFieldOfTheConsistencyCheckInTheFilesUnits) {
  // The issue's case: module_m 0.1016 for 0.01016 blamed pitch_diameter_m alone, with a double
  // space and no unit. 100 teeth * 0.1016 m = 10.16 m against a 1.016 m pitch diameter.
  EXPECT_EQ(message_of([] { parse_coupling_text(upwind_with("module_m", "0.1016"), "typo.textproto"); }),
            "coupling.pitch_diameter_m = 1.016 m and coupling.teeth * coupling.module_m = "
            "100 * 0.1016 m = 10.16 m disagree: the pitch diameter is N * module within 0.5 %; "
            "one of the three is wrong (in typo.textproto)");
}

TEST(CouplingFile, BaseDiameterCheckNamesPitchDiameterAndPressureAngleInDegrees) {
  const std::string message = message_of(
      [] { parse_coupling_text(upwind_with("base_diameter_m", "0.9"), "base.textproto"); });
  // 1.016 m * cos(20 deg) = 0.954728 m (Table 1 rounds it to 0.95473).
  EXPECT_EQ(message, "coupling.base_diameter_m = 0.9 m and coupling.pitch_diameter_m * "
                     "cos(coupling.pressure_angle_deg) = 1.016 m * cos(20 deg) = 0.954728 m "
                     "disagree: the base diameter is D cos(phi) within 0.5 %; one of the three is "
                     "wrong (in base.textproto)");
}

TEST(CouplingFile, DegreeFieldOutOfRangeIsReportedInDegreesWithTheUnit) {
  try {
    parse_coupling_text(upwind_with("pressure_angle_deg", "50"), "steep.textproto");
    FAIL() << "50 deg accepted";
  } catch (const InvalidInput& error) {
    EXPECT_EQ(error.field(), "coupling.pressure_angle_deg");
    EXPECT_STREQ(error.what(), "coupling.pressure_angle_deg = 50 is out of range: allowed "
                               "[5.002, 45] deg (in steep.textproto)");
  }
  EXPECT_EQ(message_of([] { parse_coupling_text(upwind_with("tilt_deg", "-91"), "t.textproto"); }),
            "coupling.tilt_deg = -91 is out of range: allowed [-90, 90] deg (in t.textproto)");
  EXPECT_EQ(message_of([] {
              parse_coupling_text(upwind_with("design_misalignment_deg", "12"), "d.textproto");
            }),
            "coupling.design_misalignment_deg = 12 is out of range: allowed [0, 9.998] deg "
            "(in d.textproto)");
}

TEST(CouplingFile, DegreeRangesPrintedAreAcceptedByTheCore) {
  // The printed bounds are the core's radians converted and rounded inwards: a file at each
  // printed edge passes the codec and the core alike; just outside, the codec refuses in degrees
  // (so the core's message in radians is never what a file's author reads).
  const struct {
    const char* field;
    const char* inside;
    const char* outside;
  } edges[] = {{"pressure_angle_deg", "5.002", "5.0015"},  {"pressure_angle_deg", "45", "45.001"},
               {"design_misalignment_deg", "0", "-0.001"}, {"design_misalignment_deg", "9.998", "9.999"},
               {"tilt_deg", "-90", "-90.001"},             {"tilt_deg", "90", "90.001"}};
  // At another pressure angle the base diameter D cos(phi) follows.
  const auto file_with = [](const std::string& field, const std::string& value) {
    if (field != "pressure_angle_deg") return upwind_with(field, value);
    const std::string base = std::to_string(1.016 * std::cos(std::stod(value) * M_PI / 180.0));
    return without_line_of(upwind_with(field, value), "base_diameter_m:") + "base_diameter_m: " + base + "\n";
  };
  for (const auto& edge : edges) {
    const CouplingDefinition d = parse_coupling_text(file_with(edge.field, edge.inside), "edge.textproto");
    EXPECT_NO_THROW(CouplingGeometry{d}) << edge.field << " = " << edge.inside;
    EXPECT_NE(message_of([&] {
                parse_coupling_text(file_with(edge.field, edge.outside), "edge.textproto");
              }).find(std::string("coupling.") + edge.field + " = " + edge.outside + " is out of range"),
              std::string::npos)
        << edge.field << " = " << edge.outside;
  }
}

}  // namespace
}  // namespace gc::codec

namespace gc::codec {
namespace {

// A coupling as JSON (a Python dict) reads through the text parser: the same definition, the
// same errors.
TEST(CouplingJson, EqualsTheTextItWasWrittenFrom) {
  const CouplingDefinition text = parse_coupling_text(bundled_text("nrel_upwind"), "upwind");
  const std::string json = R"({"name": "nrel_upwind", "teeth": 100, "module_m": 0.01016,
    "pressure_angle_deg": 20.0, "pitch_diameter_m": 1.016, "base_diameter_m": 0.95473,
    "outer_diameter_m": 1.03632, "root_diameter_m": 0.98877, "center_distance_m": 0.0,
    "backlash_m": 0.00064, "tooth_thickness_m": 0.01555, "tool_tip_radius_m": 0.00427,
    "facewidth_m": 0.127, "lead_modification_m": 0.00078, "profile_tip_relief_m": 0.00046,
    "profile_relief_start_roll_deg": 23.6, "form_factor_hub": 0.45, "form_factor_sleeve": 0.45,
    "youngs_modulus_pa": 2.06e11, "poisson_ratio": 0.3, "design_misalignment_deg": 0.0,
    "coupling_weight_n": 24000, "shaft_weight_per_length_n_per_m": 21100, "shaft_length_m": 2.8,
    "tilt_deg": 0.0, "allowables": {"contact_stress_pa": 1.1e9, "bending_stress_pa": 3.1e8}})";
  const CouplingDefinition parsed = parse_coupling_json(json, "dict");
  EXPECT_EQ(parsed.name, text.name);
  EXPECT_EQ(parsed.teeth, text.teeth);
  EXPECT_EQ(parsed.pressure_angle_rad, text.pressure_angle_rad);
  EXPECT_EQ(parsed.lead_modification_m, text.lead_modification_m);
  EXPECT_EQ(parsed.allowables.bending_stress_pa, text.allowables.bending_stress_pa);
}

TEST(CouplingJson, MissingFieldAndUnknownFieldAreNamed) {
  try {
    parse_coupling_json(R"({"name": "x", "teeth": 10})", "dict");
    FAIL() << "accepted a coupling without its fields";
  } catch (const InvalidInput& error) {
    EXPECT_EQ(error.field().rfind("coupling.", 0), 0u) << error.field();
    EXPECT_NE(std::string(error.what()).find("dict"), std::string::npos) << error.what();
  }
  try {
    parse_coupling_json(R"({"name": "x", "no_such_field": 1})", "dict");
    FAIL() << "accepted an unknown field";
  } catch (const InvalidInput& error) {
    EXPECT_EQ(error.field(), "coupling");
    EXPECT_NE(std::string(error.what()).find("no_such_field"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace gc::codec
