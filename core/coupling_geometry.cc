#include "core/coupling_geometry.h"

#include <cmath>
#include <string>
#include <utility>

#include "core/crown_radius.h"
#include "core/model_error.h"
#include "core/tooth_stiffness.h"

namespace gc {
namespace {

// Table 1's diameters are rounded to 0.01 mm; consistency checks allow this relative slack.
constexpr double kConsistency = 5e-3;

// Upper bounds on the sizes, weights and moduli: far beyond any gear coupling (the NREL ones
// are 1 m across; the largest the service accepts, 10,000 teeth of nrel_upwind's module, is
// 100 m), and low enough that no product in eqs 1-53 can overflow (fuzz/, docs/fuzzing.md:
// a shaft length of 1e228 m gave an infinite self-weight moment).
constexpr double kMaxLengthM = 1000.0;
// Lower bounds likewise: a 1e-322 m facewidth made the mesh stiffness vanish and the sag of
// eqs 51 and 53 infinite. 0.1 um is below any machining tolerance; 1 mm below any coupling.
constexpr double kMinLengthM = 1.0e-7;
constexpr double kMinPitchDiameterM = 1.0e-3;
constexpr double kMaxCrownRadiusM = 1.0e4;     // flatter crowns: lead modification < 1e-6 F
constexpr double kMinModulusPa = 1.0e6;        // softer than rubber: eqs 5-6 lose meaning
constexpr double kMaxModulusPa = 1.0e13;       // ten times diamond
constexpr double kMaxWeightN = 1.0e9;          // 100,000 t
constexpr double kMaxWeightPerLengthNPerM = 1.0e9;
constexpr double kMaxAllowableStressPa = 1.0e12;

std::string field(const char* name) { return std::string("coupling.") + name; }

void require_consistent(const char* name, double value, double expected, const char* rule) {
  if (std::abs(value - expected) > kConsistency * std::abs(expected)) {
    throw InvalidInput(field(name), value,
                       std::string("within 0.5 % of ") + rule + " = " + format_number(expected));
  }
}

void validate_definition(const CouplingDefinition& d) {
  if (d.teeth < 8 || d.teeth > 10000) {
    throw InvalidInput(field("teeth"), d.teeth, "[8, 10000] whole teeth");
  }
  require_positive(field("module_m"), d.module_m);
  require_in_range(field("pitch_diameter_m"), d.pitch_diameter_m, kMinPitchDiameterM, kMaxLengthM);
  require_in_range(field("pressure_angle_rad"), d.pressure_angle_rad, 0.0873, 0.7854);  // 5-45 deg
  require_positive(field("pitch_diameter_m"), d.pitch_diameter_m);
  require_consistent("pitch_diameter_m", d.pitch_diameter_m, d.teeth * d.module_m, "N * module");
  require_positive(field("base_diameter_m"), d.base_diameter_m);
  require_consistent("base_diameter_m", d.base_diameter_m,
                     d.pitch_diameter_m * std::cos(d.pressure_angle_rad), "D cos(phi)");
  require_positive(field("outer_diameter_m"), d.outer_diameter_m);
  if (d.outer_diameter_m <= d.pitch_diameter_m || d.outer_diameter_m > 2.0 * d.pitch_diameter_m) {
    throw InvalidInput(field("outer_diameter_m"), d.outer_diameter_m,
                       "(D, 2 D] for the pitch diameter D = " + format_number(d.pitch_diameter_m) +
                           " m");
  }
  require_positive(field("root_diameter_m"), d.root_diameter_m);
  if (d.root_diameter_m >= d.pitch_diameter_m) {
    throw InvalidInput(field("root_diameter_m"), d.root_diameter_m,
                       "< pitch diameter " + format_number(d.pitch_diameter_m) + " m");
  }
  require_in_range(field("center_distance_m"), d.center_distance_m, 0.0, kMaxLengthM);
  require_positive(field("backlash_m"), d.backlash_m);
  require_in_range(field("backlash_m"), d.backlash_m, kMinLengthM, kMaxLengthM);
  require_positive(field("tooth_thickness_m"), d.tooth_thickness_m);
  require_in_range(field("tooth_thickness_m"), d.tooth_thickness_m, kMinLengthM, kMaxLengthM);
  const double circular_pitch = M_PI * d.pitch_diameter_m / d.teeth;
  if (d.tooth_thickness_m + d.backlash_m >= circular_pitch) {
    throw InvalidInput(field("tooth_thickness_m"), d.tooth_thickness_m,
                       "(0, circular pitch - backlash) = (0, " +
                           format_number(circular_pitch - d.backlash_m) +
                           ") m: the sleeve tooth t_c2 = pi/P - t_c1 - b must be positive");
  }
  require_in_range(field("tool_tip_radius_m"), d.tool_tip_radius_m, 0.0, kMaxLengthM);
  require_positive(field("facewidth_m"), d.facewidth_m);
  require_in_range(field("facewidth_m"), d.facewidth_m, kMinLengthM, kMaxLengthM);
  // Below the jam angle the contact offset f_d stays within F/2 (eq 30); eq 39's moment arm
  // sqrt(R^2 - f_d^2) is real only while that is within the pitch radius R. A 5.1 m facewidth
  // on a 1 m coupling made it NaN (found by fuzz/coupling_text_fuzzer).
  if (d.facewidth_m >= d.pitch_diameter_m) {
    throw InvalidInput(field("facewidth_m"), d.facewidth_m,
                       "< the pitch diameter D = " + format_number(d.pitch_diameter_m) +
                           " m (eq 39 needs the contact offset, up to F/2, within R = D/2)");
  }
  require_in_range(field("profile_tip_relief_m"), d.profile_tip_relief_m, 0.0, kMaxLengthM);
  require_finite(field("profile_relief_start_roll_rad"), d.profile_relief_start_roll_rad);
  if (d.crown_radius_m) {
    require_positive(field("crown_radius_m"), *d.crown_radius_m);
  } else {
    require_positive(field("lead_modification_m"), d.lead_modification_m);
  }
  require_in_range(field("form_factor_hub"), d.form_factor_hub, 0.05, 1.0);
  require_in_range(field("form_factor_sleeve"), d.form_factor_sleeve, 0.05, 1.0);
  require_in_range(field("youngs_modulus_pa"), d.youngs_modulus_pa, kMinModulusPa, kMaxModulusPa);
  require_in_range(field("poisson_ratio"), d.poisson_ratio, 0.0, 0.49);
  require_in_range(field("design_misalignment_rad"), d.design_misalignment_rad, 0.0, 0.1745);
  require_in_range(field("coupling_weight_n"), d.coupling_weight_n, 0.0, kMaxWeightN);
  require_in_range(field("shaft_weight_per_length_n_per_m"), d.shaft_weight_per_length_n_per_m,
                   0.0, kMaxWeightPerLengthNPerM);
  require_in_range(field("shaft_length_m"), d.shaft_length_m, 0.0, kMaxLengthM);
  require_in_range(field("tilt_rad"), d.tilt_rad, -1.5708, 1.5708);
  if (d.sleeve_root_diameter_m && !(*d.sleeve_root_diameter_m > d.outer_diameter_m &&
                                    *d.sleeve_root_diameter_m <= 2.0 * d.pitch_diameter_m)) {
    throw InvalidInput(field("sleeve_root_diameter_m"), *d.sleeve_root_diameter_m,
                       "(hub outer diameter " + format_number(d.outer_diameter_m) +
                           " m, 2 D = " + format_number(2.0 * d.pitch_diameter_m) + " m]");
  }
  for (const auto& [name, stress] : {std::pair{"allowables.contact_stress_pa", d.allowables.contact_stress_pa},
                                     {"allowables.bending_stress_pa", d.allowables.bending_stress_pa}}) {
    require_positive(field(name), stress);
    require_in_range(field(name), stress, 0.0, kMaxAllowableStressPa);
  }
}

}  // namespace

CouplingGeometry::CouplingGeometry(CouplingDefinition definition)
    : definition_(std::move(definition)) {
  const CouplingDefinition& d = definition_;
  validate_definition(d);
  // Once per coupling, not per sample: eqs 7 and 11 take them for every prediction.
  cos_pressure_angle_ = std::cos(d.pressure_angle_rad);
  tan_pressure_angle_ = std::tan(d.pressure_angle_rad);
  diametral_pitch_ = d.teeth / d.pitch_diameter_m;     // P = N / D [1/m]
  pitch_radius_m_ = d.teeth / (2.0 * diametral_pitch_);  // eq 8
  circular_pitch_m_ = M_PI / diametral_pitch_;
  sleeve_space_width_m_ = d.tooth_thickness_m + d.backlash_m;    // S_c2 = t_c1 + b
  sleeve_tooth_m_ = circular_pitch_m_ - sleeve_space_width_m_;   // eq 27
  crown_radius_m_ = d.crown_radius_m ? *d.crown_radius_m
                                     : crown_radius_from_lead_modification(
                                           d.facewidth_m, d.lead_modification_m);
  if (!(crown_radius_m_ > 0.5 * d.facewidth_m && crown_radius_m_ <= kMaxCrownRadiusM)) {
    // A derived radius is the lead modification's doing: name the field the user wrote.
    throw InvalidInput(field(d.crown_radius_m ? "crown_radius_m" : "lead_modification_m"),
                       d.crown_radius_m ? crown_radius_m_ : d.lead_modification_m,
                       "a crown radius R_F in (F/2 = " + format_number(0.5 * d.facewidth_m) +
                           ", " + format_number(kMaxCrownRadiusM) + "] m (here " +
                           format_number(crown_radius_m_) + " m)");
  }
  root_crown_radius_m_ =
      crown_radius_m_ * std::cos(d.design_misalignment_rad) * std::sin(d.pressure_angle_rad);  // 12
  stiffness_ = single_pair_stiffness(d.facewidth_m, d.youngs_modulus_pa, d.form_factor_hub,
                                     d.form_factor_sleeve);  // eqs 5-6
  // Working depth: the hub addendum is (D_o - D)/2; the sleeve's is taken equal (stress.h).
  working_depth_m_ = d.outer_diameter_m - d.pitch_diameter_m;
  sleeve_root_diameter_m_ =
      d.sleeve_root_diameter_m.value_or(2.0 * d.pitch_diameter_m - d.root_diameter_m);
  jam_angle_ = gc::jam_angle(JamGeometry{crown_radius_m_, d.tooth_thickness_m,
                                         sleeve_space_width_m_, d.facewidth_m,
                                         d.pressure_angle_rad, d.backlash_m});
  tooth_angle_rad_.resize(d.teeth);
  tooth_sin_.resize(d.teeth);
  tooth_cos_.resize(d.teeth);
  for (int j = 0; j < d.teeth; ++j) {
    tooth_angle_rad_[j] = 2.0 * M_PI * j / d.teeth;
    tooth_sin_[j] = std::sin(tooth_angle_rad_[j]);
    tooth_cos_[j] = std::cos(tooth_angle_rad_[j]);
  }
}

}  // namespace gc
