// What the DAQ export does to the record as written: the ADC step of the moment channels (with
// the other noise as dither, the step at most twice its RMS, so the rounding error is noise and
// not a function of the signal), and jitter of the time stamps (the sample is taken on the
// clock; the stamp written wanders by a fraction of the period, never backwards).
#include <algorithm>
#include <cmath>

#include "tests/diagnosis/zoo/families.h"
#include "tests/diagnosis/zoo/text.h"

namespace gc::zoo {

std::string adc_quantisation(const NoiseContext& c, Rng& rng, Channels& out) {
  const double step = rng.uniform(0.2, 2.0) * c.level_nm;
  for (auto* ch : {&out.msy_nm, &out.msz_nm}) {
    for (double& v : *ch) v = step * std::round(v / step);
  }
  return format("ADC step %.0f N·m (%.2fx the noise)", step, step / c.level_nm);
}

std::string stamp_jitter(const NoiseContext& c, Rng& rng, Channels& out) {
  const double sd = rng.uniform(0.01, 0.25) / c.fs_hz;
  for (std::size_t i = 0; i < out.rows(); ++i) {
    out.time_s[i] += sd * rng.normal();
    if (i > 0) out.time_s[i] = std::max(out.time_s[i], out.time_s[i - 1]);
  }
  return format("stamp jitter %.3g s (%.0f%% of the period)", sd, 100 * sd * c.fs_hz);
}

}  // namespace gc::zoo
