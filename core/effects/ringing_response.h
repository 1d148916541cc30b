// A rig's own dynamics seen by the moment channels: a lightly damped mode (the rig's structure, a
// stiff shaft, the dynamometer's torsional mode) excited by a change of the load rings after it.
// The input u (the torque) passed through a second-order system of natural frequency f_n and
// damping ratio zeta,
//   x'' + 2 zeta w_n x' + w_n^2 x = w_n^2 u,   w_n = 2 pi f_n,
// and taken relative to the input, r = h * u - u: zero at steady state, a decaying oscillation
// after each change. The input is held between samples (zero-order hold), so a change
// du_j = u_j - u_{j-1} at time t_j adds du_j g(t - t_j), g the step response less one:
//   g(tau) = -e^{-zeta w_n tau} (cos w_d tau + zeta / sqrt(1 - zeta^2) sin w_d tau)
//          = Re(A e^{s tau}),  s = -zeta w_n + i w_d,  A = -1 + i zeta / sqrt(1 - zeta^2),
// w_d = w_n sqrt(1 - zeta^2). A sequence starts at rest (u_{-1} = u_0).
#pragma once

#include <span>
#include <vector>

#include "core/input_history.h"

namespace gc {

struct RingingMode {
  double natural_frequency_hz = 0.0;  ///< f_n [Hz], > 0
  double damping_ratio = 0.0;         ///< zeta [-], in (0, 1)
};

/// r at every sample of a sequence (`times_s` [s] non-decreasing, `inputs` in the input's unit), in
/// one pass: S_i = S_{i-1} e^{s (t_i - t_{i-1})} + A du_i, r_i = Re S_i [input's unit].
std::vector<double> ringing_sequence(std::span<const double> times_s, std::span<const double> inputs,
                                     const RingingMode& mode);

/// How long a change of the input rings: e^{-zeta w_n tau} < 1e-6 after it [s].
double ringing_memory_s(const RingingMode& mode);

/// r of the torque at the history's sample alone, summed over the changes before it back to
/// ringing_memory_s (and the one change into that stretch): what a model that holds no state
/// computes for one sample [N·m].
double torque_ringing_at(const InputHistory& history, const RingingMode& mode);

}  // namespace gc
