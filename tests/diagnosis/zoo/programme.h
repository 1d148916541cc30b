// Random test programmes: the TRUE inputs of a noise-only recording. A sequence of 1-6 blocks of
// random kinds and durations (torque staircases, misalignment sweeps, ramps, random OU blocks,
// direction sweeps, holds), joined by ramps, within the limits of the coupling's test cell. The
// speed per block constant or ramped (3-15 rpm); the oil temperature a first-order lag towards a
// load-dependent level. All SI (speed rpm, temperature deg C).
#pragma once

#include <cstddef>
#include <string>

#include "tests/diagnosis/zoo/channels.h"
#include "tests/diagnosis/zoo/rng.h"

namespace gc::zoo {

struct ProgrammeLimits {
  double torque_min_nm = 0.1e6;
  double torque_max_nm = 2.6e6;
  double zeta_min_rad = 0.0;   ///< kept above zero: the probes' vector noise would bias a zero amplitude
  double zeta_max_rad = 0.0;   ///< about 60 % of the jam angle
  double speed_min_rpm = 3.0;
  double speed_max_rpm = 15.0;
  int first_block = -1;       ///< -1: drawn; 0: a torque staircase; 1: misalignment sweeps (power mode's needs)
  bool vary_speed = false;    ///< every block ends at another speed (power mode's needs)
};

struct Programme {
  Channels truth;              ///< inputs filled, moments zero
  std::string description;     ///< e.g. "staircase(T) > sweep > ou"
};

Programme draw_programme(std::size_t rows, double fs_hz, const ProgrammeLimits& limits, Rng& rng);

}  // namespace gc::zoo
