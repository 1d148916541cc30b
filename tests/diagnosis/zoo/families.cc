#include "tests/diagnosis/zoo/families.h"

namespace gc::zoo {

const std::vector<Family>& all_families() {
  static const std::vector<Family> families = {
      {"white", FamilyKind::moment, white_gaussian},
      {"student_t", FamilyKind::moment, student_t},
      {"laplace", FamilyKind::moment, laplace},
      {"ar1", FamilyKind::moment, ar1_coloured},
      {"ar2_resonant", FamilyKind::moment, ar2_resonant_noise},
      {"pink", FamilyKind::moment, pink_noise},
      {"brown", FamilyKind::moment, brown_noise},
      {"hidden_correlated", FamilyKind::moment, hidden_correlated},
      {"wandering_zero", FamilyKind::moment, wandering_zero},
      {"band_limited", FamilyKind::moment, band_limited},
      {"moving_average", FamilyKind::moment, moving_average_noise},
      {"sample_and_hold", FamilyKind::moment, sample_and_hold},
      {"demodulator", FamilyKind::moment, demodulator_average},
      {"slow_heteroscedastic", FamilyKind::moment, slow_heteroscedastic},
      {"torque_heteroscedastic", FamilyKind::moment, torque_heteroscedastic},
      {"garch", FamilyKind::moment, garch_clusters},
      {"cross_correlated", FamilyKind::moment, cross_correlated},
      {"telegraph", FamilyKind::moment, burst_telegraph},
      {"spikes", FamilyKind::moment, isolated_spikes},
      {"mains", FamilyKind::moment, mains_pickup},
      {"adc_step", FamilyKind::exporting, adc_quantisation},
      {"stamp_jitter", FamilyKind::exporting, stamp_jitter},
      {"torque_sensor", FamilyKind::input, torque_transducer},
      {"probes", FamilyKind::input, proximity_probes},
      {"tachometer", FamilyKind::input, tachometer},
      {"oil_rtd", FamilyKind::input, oil_rtd},
  };
  return families;
}

const Family* find_family(const std::string& name) {
  for (const Family& f : all_families()) {
    if (name == f.name) return &f;
  }
  return nullptr;
}

}  // namespace gc::zoo
