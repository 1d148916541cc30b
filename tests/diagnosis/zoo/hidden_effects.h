// The zoo's power mode: a hidden physical effect under the noise, written here from the physics
// (the paper's equations and what the effect is in a rig; not from the effects library), scaled
// so that its RMS on the moments is `snr` times the noise level. The model diagnose is given
// (the paper's {friction mu0 0.1, pressure_angle_rotation, self_weight}) lacks it; naming it
// first is a hit.
//
// The four first truths:
//   torque_gain          the torque transducer reads off by a gain: the coupling carries
//                        (1 + g) times the logged torque, |g| 1-5 % either sign (the moments at the
//                        carried torque)
//   misalignment_offset  an unseen constant misalignment vector, 0.02 xi (times the solved size,
//                        at most 0.3 xi) at any direction, summed with the recorded vector (the
//                        moments at the sum)
//   twice_per_rev        an oval sleeve: (A cos(2 phi + p), A sin(2 phi + p)), phi the shaft angle
//   weight               a heavier hub: M_sy' lower by a constant
// The first two are solved physically like the effects below (they were once a trial change
// scaled linearly, which is wrong for them: the number of teeth summed, int(qN/4), steps as the
// torque or the misalignment changes, so the model's moments jump, and a 1 % change scaled by k
// puts the jumps where no gain or offset of any size has them); the last two are additive
// signals, linear by construction: their unit shape is scaled.
#pragma once

#include <string>
#include <vector>

#include "core/coupling_model.h"
#include "tests/diagnosis/zoo/channels.h"
#include "tests/diagnosis/zoo/rng.h"

namespace gc::zoo {

struct HiddenEffectInfo {
  std::string name;
  std::string physics;   ///< one line: the physics and the drawn ranges
  std::string pattern;   ///< regular expression a first claim's name must match (ECMAScript)
  std::string counts;    ///< the names that count, for tables
};

const std::vector<HiddenEffectInfo>& hidden_effect_table();
const std::vector<std::string>& hidden_effect_names();
/// Regular expression a claimed name must match to name the effect.
std::string hidden_effect_pattern(const std::string& name);

/// What the programme must contain for the effect to show at all (ProgrammeLimits).
struct ProgrammeNeeds {
  int first_block = -1;     ///< -1 any; 0 a torque staircase (from low torque up); 1 misalignment sweeps
  bool vary_speed = false;  ///< every block ends at another speed
};
ProgrammeNeeds hidden_effect_programme(const std::string& name);

/// Adds the effect to truth's moments (RMS of the change over both channels = snr * level_nm);
/// returns its parameters as text. Throws std::invalid_argument for an unknown name.
std::string add_hidden_effect(const std::string& name, double snr, double level_nm, const CouplingModel& model,
                              double jam_rad, Channels& truth, Rng& rng);

}  // namespace gc::zoo
