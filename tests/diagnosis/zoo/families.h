// The noise families of the zoo: each a kind of noise a test cell's DAQ really produces, with its
// parameters drawn at random within physically plausible ranges. None carries deterministic
// structure a physicist would call an effect (no fixed tone, no step, no gain, no lag of the
// moment channels): a recording made with them is noise on the model's own prediction.
//
// Three kinds:
//  - moment: additive noise on M_sy', M_sz' of a given RMS level [N·m] (centred: a constant
//    offset is a calibration error, not noise);
//  - input: noise on the logged inputs (torque transducer, proximity probes, tachometer, RTD).
//    The moments stay the model's prediction at the TRUE inputs, so the model fed the logged
//    inputs predicts noisy moments: errors in the variables, not physics;
//  - export: what the DAQ does to the whole record as written (ADC quantisation of the moment
//    channels, jitter of the time stamps). Applied after the others.
#pragma once

#include <string>
#include <vector>

#include "tests/diagnosis/zoo/channels.h"
#include "tests/diagnosis/zoo/rng.h"
#include "tests/diagnosis/zoo/series.h"

namespace gc::zoo {

enum class FamilyKind { moment, input, exporting };

struct NoiseContext {
  const Channels* truth = nullptr;  ///< the true run (clean moments)
  double fs_hz = 10.0;              ///< sample rate [Hz]
  double level_nm = 0.0;            ///< moment: this family's RMS [N·m]; export: the whole moment noise's RMS
  double moment_range_nm = 0.0;     ///< spread of the clean moments (larger channel) [N·m]
  double torque_span_nm = 0.0;      ///< spread of the true torque [N·m]
  double jam_rad = 0.0;             ///< the coupling's jam angle [rad]
};

/// Adds the family's noise to `logged` (moment channels for moment families, inputs for input
/// families, stamps or rounding for export families) and returns its parameters as text.
using FamilyFn = std::string (*)(const NoiseContext&, Rng&, Channels& logged);

struct Family {
  const char* name;
  FamilyKind kind;
  FamilyFn apply;
};

/// Every family, in a fixed order (the order is part of what a seed reproduces).
const std::vector<Family>& all_families();
const Family* find_family(const std::string& name);

// Families by file (each file one idea).
std::string white_gaussian(const NoiseContext&, Rng&, Channels&);        // white_noise.cc
std::string student_t(const NoiseContext&, Rng&, Channels&);
std::string laplace(const NoiseContext&, Rng&, Channels&);
std::string ar1_coloured(const NoiseContext&, Rng&, Channels&);          // coloured_noise.cc
std::string ar2_resonant_noise(const NoiseContext&, Rng&, Channels&);
std::string pink_noise(const NoiseContext&, Rng&, Channels&);
std::string brown_noise(const NoiseContext&, Rng&, Channels&);
std::string hidden_correlated(const NoiseContext&, Rng&, Channels&);
std::string wandering_zero(const NoiseContext&, Rng&, Channels&);
std::string band_limited(const NoiseContext&, Rng&, Channels&);          // filtered_noise.cc
std::string moving_average_noise(const NoiseContext&, Rng&, Channels&);
std::string sample_and_hold(const NoiseContext&, Rng&, Channels&);
std::string demodulator_average(const NoiseContext&, Rng&, Channels&);
std::string slow_heteroscedastic(const NoiseContext&, Rng&, Channels&);  // modulated_noise.cc
std::string torque_heteroscedastic(const NoiseContext&, Rng&, Channels&);
std::string garch_clusters(const NoiseContext&, Rng&, Channels&);
std::string cross_correlated(const NoiseContext&, Rng&, Channels&);
std::string burst_telegraph(const NoiseContext&, Rng&, Channels&);
std::string isolated_spikes(const NoiseContext&, Rng&, Channels&);
std::string mains_pickup(const NoiseContext&, Rng&, Channels&);          // pickup_noise.cc
std::string adc_quantisation(const NoiseContext&, Rng&, Channels&);      // daq_export.cc
std::string stamp_jitter(const NoiseContext&, Rng&, Channels&);
std::string torque_transducer(const NoiseContext&, Rng&, Channels&);     // input_sensors.cc
std::string proximity_probes(const NoiseContext&, Rng&, Channels&);
std::string tachometer(const NoiseContext&, Rng&, Channels&);
std::string oil_rtd(const NoiseContext&, Rng&, Channels&);

/// Adds a (unit-free) pair of series scaled to `rms` [N·m] to the moment channels.
void add_moments(Channels& logged, Series y, Series z, double rms);

}  // namespace gc::zoo
