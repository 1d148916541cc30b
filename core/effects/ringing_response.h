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

#include <array>
#include <complex>
#include <cstdint>
#include <cstring>
#include <span>
#include <vector>

#include "core/input_history.h"

namespace gc {

struct RingingMode {
  double natural_frequency_hz = 0.0;  ///< f_n [Hz], > 0
  double damping_ratio = 0.0;         ///< zeta [-], in (0, 1)
};

/// The pole s and residue A of g(tau) = Re(A e^{s tau}), stepping S_i = S_{i-1} e^{s dt} + A du.
/// For callers that use each r_i once (a score summed over rows) and need not store the sequence.
class RingingPole {
 public:
  explicit RingingPole(const RingingMode& mode);

  /// e^{s dt}, remembered per gap: a clock's gaps take a handful of values a few ulp apart (16 on
  /// a 100 Hz CSV's stamps), which alternate, and an exp per sample was a sixth of a diagnosis.
  std::complex<double> decay(double dt) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, &dt, sizeof bits);
    const std::size_t slot = static_cast<std::size_t>((bits * 0x9E3779B97F4A7C15ull) >> 58);  // of 64
    if (!(gaps_[slot] == dt)) {
      gaps_[slot] = dt;
      decays_[slot] = std::exp(s_ * dt);
    }
    return decays_[slot];
  }
  std::complex<double> a() const { return a_; }

  /// One step of the sum over a gap `dt` [s] and a change `du` of the input; r_i = Re S_i.
  double next(std::complex<double>& sum, double dt, double du) {
    sum = sum * decay(dt) + a_ * du;
    return sum.real();
  }

 private:
  std::complex<double> s_, a_;
  std::array<double, 64> gaps_;
  std::array<std::complex<double>, 64> decays_{};
};

/// r at every sample of a sequence (`times_s` [s] non-decreasing, `inputs` in the input's unit), in
/// one pass: S_i = S_{i-1} e^{s (t_i - t_{i-1})} + A du_i, r_i = Re S_i [input's unit].
std::vector<double> ringing_sequence(std::span<const double> times_s, std::span<const double> inputs,
                                     const RingingMode& mode);

/// How long a change of the input rings: e^{-zeta w_n tau} < 1e-6 after it [s].
double ringing_memory_s(const RingingMode& mode);

/// How far before a sample torque_ringing_at reads the torque [s] (and the one sample before that
/// stretch): the memory and one block (below), twice the memory.
double ringing_history_s(const RingingMode& mode);

/// r of the torque at the history's sample alone: what a model that holds no state computes for one
/// sample [N·m]. Time falls in blocks of the memory's length, floor(t / memory); every
/// sample of a block sums the changes from one anchor, the last sample at least a memory before
/// the block's start (or the first sample), stepping S forward to the sample. Each sample then sees
/// every change of its own memory and older ones forgotten below 1e-6, and the samples of a block
/// share one pass: torque_ringing_at_rows gives the same numbers, to the bit, in O(memory) a block
/// where summing back from each sample costs O(memory) a sample (a 1.06 Hz mode with a damping
/// ratio of 0.2 remembers 10.4 s, 4,150 samples at 399 Hz: a diagnosis took 358 s).
double torque_ringing_at(const InputHistory& history, const RingingMode& mode);

/// torque_ringing_at at each of `rows` (any order) of `recording` (in time order), in the order of
/// `rows`: one pass a block for rows that come in time order, to the bit the numbers of
/// torque_ringing_at.
std::vector<double> torque_ringing_at_rows(std::span<const RecordedSample> recording,
                                           std::span<const std::size_t> rows, const RingingMode& mode);

}  // namespace gc
