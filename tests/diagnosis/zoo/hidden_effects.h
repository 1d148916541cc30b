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

#include <functional>
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

/// One parameter of a truth's family of signals.
struct EffectParameter {
  std::string name;
  double lo = 0.0, hi = 0.0;  ///< the range a fit searches (lo == hi: held at that value; infinite: free)
  double scale = 1.0;         ///< a typical size: finite differences and start points where a bound is infinite
};

/// A truth's signal as a function of its parameters: the generator draws one member (its shape
/// parameters, then its size lambda solved for the SNR); a fit (identity_oracle.h) searches them
/// all. `parameters` are the generator's own (its drawn shape parameters, then lambda) with the
/// ranges of every member the generator can reach: the drawn ranges times lambda within its
/// physical bounds, the redundant lambda held at 1 where the drawn amplitudes already carry the
/// size, angles free, a size of either sign where its sign is physical. `moments(theta, i)` is the
/// rig's moments at row i of the effect-free truth `clean` with the effect at theta; it throws where
/// the model refuses the row (the generator then leaves the row unchanged). The family holds
/// references to the model and `clean`: they must outlive it.
struct HiddenEffectFamily {
  std::string name;
  std::vector<EffectParameter> parameters;
  std::vector<double> none;  ///< a member without any effect (every family has one)
  int size_parameter = -1;   ///< the parameter the change is about proportional to (its size), or -1
  /// With size_parameter: the direction of a vector whose length (either sign) is the size (an
  /// offset's direction, a phase), or -1. A fit reads the pair as the vector's two components.
  int polar_angle = -1;
  std::function<SensorMoments(const std::vector<double>& theta, std::size_t i)> moments;
  /// Brings theta back into the physical set where that is not a box (e.g. a size bound that
  /// depends on a shape parameter); empty where the box is the set.
  std::function<void(std::vector<double>& theta)> project;
};

/// The family of truth `name` (hidden_effect_table()) on the effect-free truth `clean`.
/// remember_rows: keep per-row work that does not depend on theta (the base prediction of a
/// contact change; a switch's change), for a fit evaluating the same rows many times.
/// Throws std::invalid_argument for an unknown name.
HiddenEffectFamily hidden_effect_family(const std::string& name, const CouplingModel& model, double jam_rad,
                                        const Channels& clean, bool remember_rows = false);

/// Adds the effect to truth's moments (RMS of the change over both channels = snr * level_nm);
/// returns its parameters as text. Throws std::invalid_argument for an unknown name.
std::string add_hidden_effect(const std::string& name, double snr, double level_nm, const CouplingModel& model,
                              double jam_rad, Channels& truth, Rng& rng);

}  // namespace gc::zoo
