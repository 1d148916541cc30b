// The zoo's power mode: a hidden physical effect under the noise, written here from the physics
// (not from the effects library), scaled so that its RMS on the moments is `snr` times the noise
// level. The model diagnose is given lacks it; naming it first is a hit.
//   torque_gain          the torque transducer reads low by a gain: the rig's true torque is
//                        (1 + g) times the logged one (moments of the true torque)
//   misalignment_offset  an assembly misalignment vector added to the commanded one (vector sum)
//   twice_per_rev        an oval sleeve: (A cos(2 phi + p), A sin(2 phi + p)), phi the shaft angle
//   weight               a heavier hub: M_sy' lower by a constant
#pragma once

#include <string>
#include <vector>

#include "core/coupling_model.h"
#include "tests/diagnosis/zoo/channels.h"
#include "tests/diagnosis/zoo/rng.h"

namespace gc::zoo {

const std::vector<std::string>& hidden_effect_names();
/// Regular expression a claimed name must match to name the effect.
std::string hidden_effect_pattern(const std::string& name);

/// Adds the effect to truth's moments (RMS of the change over both channels = snr * level_nm);
/// returns its parameters as text. Throws std::invalid_argument for an unknown name.
std::string add_hidden_effect(const std::string& name, double snr, double level_nm, const CouplingModel& model,
                              double jam_rad, Channels& truth, Rng& rng);

}  // namespace gc::zoo
