#include "tests/diagnosis/zoo/couplings.h"

#include <unistd.h>

#include <atomic>
#include <cmath>
#include <fstream>
#include <numbers>

#include "codec/coupling_catalog.h"
#include "codec/model_file.h"
#include "tests/diagnosis/zoo/text.h"

namespace gc::zoo {
namespace {

const char* kEffects =
    "effects { name: \"friction\" parameters { name: \"mu0\" value: 0.1 } }\n"
    "effects { name: \"pressure_angle_rotation\" }\n"
    "effects { name: \"self_weight\" }\n";

// A coupling scaled from the upwind NREL coupling's proportions (data/couplings/nrel_upwind.textproto):
// addendum 1.0 module, dedendum 1.34 module, tooth thickness pi m / 2 less about half the backlash.
ModelChoice scaled(Rng& rng) {
  const double d = 1.016 * rng.uniform(0.4, 1.5);           // pitch diameter [m]
  const int teeth = rng.integer(50, 150);
  const double m = d / teeth;                                 // module [m]
  const double phi_deg = rng.chance(0.5) ? 20.0 : std::vector<double>{14.5, 17.5, 22.5, 25.0}[rng.integer(0, 3)];
  const double f = d * rng.uniform(0.08, 0.2);                // face width [m]
  const double crown = f * rng.uniform(8.0, 40.0);            // crown radius R_F [m]
  const double lead = crown - std::sqrt(crown * crown - f * f / 4.0);  // R_F = ((F/2)^2 + d^2) / (2 d)
  const double backlash = 0.00064 * m / 0.01016 * rng.uniform(0.5, 3.0);
  const double scale = (d / 1.016) * (d / 1.016) * (f / 0.127);
  const double shaft_length = rng.uniform(1.5, 4.0);
  const double tilt = rng.chance(0.7) ? 0.0 : rng.uniform(0.0, 5.0);
  ModelChoice c;
  c.torque_scale = scale;
  c.description = format("scaled N %d D %.3f m phi %.1f F %.3f m R_F %.2f m backlash %.2f mm", teeth, d, phi_deg, f, crown, backlash * 1e3);
  c.coupling_text = format(
      "name: \"zoo_scaled\"\n"
      "description: \"noise zoo: %s\"\n"
      "teeth: %d\nmodule_m: %.9g\npressure_angle_deg: %.6g\npitch_diameter_m: %.9g\nbase_diameter_m: %.9g\n"
      "outer_diameter_m: %.9g\nroot_diameter_m: %.9g\ncenter_distance_m: 0.0\nbacklash_m: %.9g\n"
      "tooth_thickness_m: %.9g\ntool_tip_radius_m: %.9g\nfacewidth_m: %.9g\nlead_modification_m: %.9g\n"
      "profile_tip_relief_m: %.9g\nprofile_relief_start_roll_deg: 23.6\nform_factor_hub: 0.45\nform_factor_sleeve: 0.45\n"
      "youngs_modulus_pa: 2.06e11\npoisson_ratio: 0.3\ndesign_misalignment_deg: 0.0\ncoupling_weight_n: %.9g\n"
      "shaft_weight_per_length_n_per_m: %.9g\nshaft_length_m: %.6g\ntilt_deg: %.6g\n"
      "allowables { contact_stress_pa: 1.1e9 bending_stress_pa: 3.1e8 }\n",
      c.description.c_str(), teeth, m, phi_deg, d, d * std::cos(phi_deg * std::numbers::pi / 180.0), d + 2.0 * m,
      d - 2.0 * 1.34 * m, backlash, std::numbers::pi * m / 2.0 - 0.6 * backlash, 0.00427 * m / 0.01016, f, lead,
      0.00046 * m / 0.01016, 24000.0 * scale, 21100.0 * (d / 1.016) * (d / 1.016), shaft_length, tilt);
  c.name = "zoo_scaled";
  c.model_text = "name: \"zoo_scaled\"\ndescription: \"the paper's effects on a scaled coupling\"\ncoupling_file: \"coupling.textproto\"\n" +
                 std::string(kEffects);
  return c;
}

}  // namespace

ModelChoice draw_model(Rng& rng, double bundled_share) {
  if (rng.chance(bundled_share)) {
    const bool up = rng.chance(0.5);
    ModelChoice c;
    c.name = up ? "paper" : "paper_downwind";
    c.description = up ? "nrel_upwind" : "nrel_downwind";
    c.model_text = "name: \"" + c.name + "\"\ncoupling: \"" + c.description + "\"\n" + kEffects;
    return c;
  }
  // A scaled draw the geometry refuses is drawn again (a few tries, then the upwind coupling).
  for (int tries = 0; tries < 20; ++tries) {
    ModelChoice c = scaled(rng);
    try {
      load_choice(c);
      return c;
    } catch (const std::exception&) {
    }
  }
  return draw_model(rng, 1.0);
}

std::filesystem::path write_choice(const ModelChoice& choice, const std::filesystem::path& dir) {
  std::filesystem::create_directories(dir);
  const auto model = dir / "model.textproto";
  std::ofstream(model) << choice.model_text;
  if (!choice.coupling_text.empty()) std::ofstream(dir / "coupling.textproto") << choice.coupling_text;
  return model;
}

std::shared_ptr<const CouplingModel> load_choice(const ModelChoice& choice) {
  static std::atomic<int> counter{0};
  const auto dir = std::filesystem::temp_directory_path() /
                   ("gc_zoo_model_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
  const auto path = write_choice(choice, dir);
  struct Cleanup {
    std::filesystem::path d;
    ~Cleanup() {
      std::error_code ignored;
      std::filesystem::remove_all(d, ignored);
    }
  } cleanup{dir};
  return std::make_shared<const CouplingModel>(codec::load_model_file(path, codec::default_catalog_dir()));
}

}  // namespace gc::zoo
