// One draw of the noise zoo: a random coupling and model, a random test programme at a random
// sample rate and length, the model's own prediction at the true inputs, and 1-3 noise families
// (moment noise, input-sensor noise, export defects) with random parameters at a random overall
// level (0.5-5 % of the moments' range by default). The recording is the logged inputs and the
// noisy moments; diagnose is given the same model, so the truth is exactly the model and any
// claim of a missing effect is false.
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "tests/diagnosis/zoo/channels.h"
#include "tests/diagnosis/zoo/couplings.h"
#include "tests/diagnosis/zoo/csv.h"

namespace gc::zoo {

struct DrawLimits {
  std::size_t min_rows = 1000, max_rows = 200000;  ///< log-uniform
  double min_rate_hz = 1.0, max_rate_hz = 1000.0;  ///< log-uniform, 3 significant digits
  double min_level = 0.005, max_level = 0.05;      ///< moment noise RMS / moments' range, log-uniform
  int min_families = 1, max_families = 3;
  double bundled_share = 0.5;                      ///< share of draws on a bundled NREL coupling
  double style_share = 0.25;                       ///< share of draws exported in other units
  std::vector<std::string> only_families;          ///< when set: exactly these (unit tests)
  bool keep_channels = false;                      ///< keep truth and logged in the draw (unit tests)
  std::string effect_truth;                        ///< power mode: a hidden effect (hidden_effects.h), empty for none
  double effect_snr = 1.0;                         ///< its RMS / the moment noise level
};

struct ZooDraw {
  std::uint64_t seed = 0;
  std::string csv;                   ///< the recording
  ModelChoice model;                 ///< the model file to give diagnose (and its coupling file)
  std::string description;           ///< one line: sizes, model, programme, level, families with parameters, units
  std::vector<std::string> families; ///< names drawn
  std::size_t rows = 0;
  double fs_hz = 0.0;
  double level_share = 0.0;          ///< moment noise RMS / moments' range
  double level_nm = 0.0;             ///< moment noise RMS asked for [N·m]
  double moment_range_nm = 0.0;      ///< spread of the clean moments (the larger channel) [N·m]
  Channels truth, logged;            ///< only with DrawLimits::keep_channels
  /// Power mode: the best power of any 1 % test that knew the effect's signal and the noise's
  /// spectrum (oracle.h); its d (>= 3.61 for 90 %). NaN without an effect, or where the noise
  /// is not finite.
  double oracle_d = std::numeric_limits<double>::quiet_NaN();
  double oracle_power = std::numeric_limits<double>::quiet_NaN();
  /// Power mode: whether the effect can be told apart from every other effect at all
  /// (identity_oracle.h): d_identity, the whitened distance of its signal from the nearest member
  /// of the nearest rival family (>= 3.61: a 1 % test tells them apart 90 % of the time), its
  /// power, and that rival. NaN and empty without an effect or a detection bound.
  double identity_d = std::numeric_limits<double>::quiet_NaN();
  double identity_power = std::numeric_limits<double>::quiet_NaN();
  std::string identity_rival;
};

ZooDraw draw(std::uint64_t seed, const DrawLimits& limits = {});

/// The seed of draw k of a run with master seed `master` (so draw k can be rerun alone).
std::uint64_t draw_seed(std::uint64_t master, std::size_t k);

}  // namespace gc::zoo
