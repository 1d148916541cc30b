#include "tests/diagnosis/campaign/daq_noise.h"

#include <algorithm>
#include <cmath>

#include "tests/diagnosis/campaign/programme.h"
#include "tests/diagnosis/independent/test_cell_noise.h"

namespace gc::campaign {
namespace {

using independent::NoiseStream;

// Student-t with 3 degrees of freedom: Z / sqrt(chi2_3 / 3).
double student_t3(NoiseStream& s) {
  const double z = s.standard_normal();
  double chi2 = 0.0;
  for (int k = 0; k < 3; ++k) {
    const double n = s.standard_normal();
    chi2 += n * n;
  }
  return z / std::sqrt(chi2 / 3.0);
}

// One channel's additive noise.
std::vector<double> channel(const NoiseSpec& spec, std::size_t rows, std::uint64_t seed) {
  NoiseStream white(seed ^ 0x1111), ar(seed ^ 0x2222), level(seed ^ 0x3333), spikes(seed ^ 0x4444),
      drift(seed ^ 0x5555);
  std::vector<double> out(rows, 0.0);
  const double phi = std::exp(-kDt / spec.ar_tau_s);
  const double a_level = std::exp(-kDt / 300.0), a_drift = std::exp(-kDt / 2000.0);
  double x = spec.ar_sigma_nm * ar.standard_normal();
  double log_level = 0.4 * level.standard_normal();
  double d = spec.drift_nm * drift.standard_normal();
  for (std::size_t i = 0; i < rows; ++i) {
    double v = spec.t3_scale_nm * student_t3(white);
    if (spec.ar_sigma_nm > 0.0) {
      // The level factor: log of it an OU process of std 0.4 (tau 300 s), clipped to [0.5, 2].
      log_level = a_level * log_level + std::sqrt(1 - a_level * a_level) * 0.4 * level.standard_normal();
      const double factor = spec.ar_level_wanders ? std::exp(std::clamp(log_level, std::log(0.5), std::log(2.0))) : 1.0;
      if (i > 0) x = phi * x + std::sqrt(1 - phi * phi) * spec.ar_sigma_nm * factor * ar.standard_normal();
      v += x;
    }
    if (spec.spike_share > 0.0 && spikes.uniform() < spec.spike_share) {
      const double sign = spikes.uniform() < 0.5 ? -1.0 : 1.0;
      v += sign * spec.spike_nm * (0.7 + 0.6 * spikes.uniform());
    }
    if (spec.drift_nm > 0.0) {
      d = a_drift * d + std::sqrt(1 - a_drift * a_drift) * spec.drift_nm * drift.standard_normal();
      v += d;
    }
    out[i] = v;
  }
  return out;
}

}  // namespace

NoiseSpec standard_daq() {
  NoiseSpec s;
  s.t3_scale_nm = 800.0;     // std 1.39 kN·m
  s.ar_sigma_nm = 1500.0;    // 1.5 kN·m x a factor 0.5-2, tau 1.5 s
  s.ar_tau_s = 1.5;
  s.ar_level_wanders = true;
  s.spike_share = 0.001;
  s.spike_nm = 25000.0;
  s.drift_nm = 600.0;
  s.lsb_nm = 200.0;
  s.duplicate_share = 0.003;
  return s;
}

DaqNoise draw_noise(const NoiseSpec& spec, std::size_t rows, std::uint64_t seed) {
  DaqNoise n;
  const std::vector<double> y = channel(spec, rows, seed * 2654435761ULL + 1);
  const std::vector<double> z = channel(spec, rows, seed * 2654435761ULL + 0x632be59bd9b4e019ULL);
  n.moments.resize(rows);
  for (std::size_t i = 0; i < rows; ++i) n.moments[i] = {y[i], z[i]};
  NoiseStream defects(seed ^ 0xdefec7);
  n.duplicate_time.assign(rows, false);
  for (std::size_t i = 1; i < rows; ++i) n.duplicate_time[i] = defects.uniform() < spec.duplicate_share;
  n.empty_column.assign(rows, -1);
  for (int k = 0; k < spec.empty_cells && rows > 10; ++k) {
    const auto i = static_cast<std::size_t>(defects.uniform() * static_cast<double>(rows - 2)) + 1;
    n.empty_column[i] = 1 + static_cast<int>(defects.uniform() * 6.0) % 7;  // any column but time
  }
  return n;
}

double quantise(double value, double lsb) { return lsb > 0.0 ? lsb * std::round(value / lsb) : value; }

}  // namespace gc::campaign
