// A second oracle for power-mode draws: can the hidden effect be told apart from every OTHER
// effect at all? The detection oracle (oracle.h) asks whether the effect's signal stands out of
// the noise; a diagnosis must also say WHICH effect it is, and some effects make the same change
// of the moments as another of some size and shape (a mesh compliance and a torque calibration
// both scale the moments with torque; an eccentricity whose torque threshold the programme never
// reaches is an assembly misalignment).
//
// For the truth E's signal s_E (what it added to the true moments) and a rival family F with
// parameters theta (hidden_effects.h: shape parameters and size over their physical ranges), the
// distance of E from F in the noise's whitened metric is
//   d_F^2 = min over theta of (s_E - s_F(theta))' Sigma^-1 (s_E - s_F(theta)),
// Sigma the draw's noise covariance, whitened exactly as oracle.h does (per channel a Burg
// autoregression, order by AIC, at most 64 or n/10; the innovations correlated at lag 0). The
// best test of "E" against "the nearest member of F", both known, moves by d_F; at 1 % one-sided
// its power is Phi(d_F - z_0.01). With d_identity = min over rivals of d_F, the truth is
// IDENTIFIABLE when d_identity >= 3.61 (90 % power at 1 %) and the detection d >= 3.61. Below it no
// test tells E from its nearest rival reliably, so a miss there is one of identity, not of power.
//
// Rivals: every other truth of hidden_effect_table() whose name E's pattern would not count as a
// hit, and whose own pattern would not count E's name either (a zoo label and the library name of
// the same physics, e.g. misalignment_offset's "misalignment" and assembly_misalignment, are one
// effect, not rivals: the name that reports one is a hit for the other). Dropping those can only
// raise d_identity.
//
// Approximations, each in the conservative direction unless said:
// - The fit is good, not optimal. Start points: the family's no-effect member and `starts` drawn
//   over its ranges, each moved to the best scalar multiple of its size, ranked by shape (the
//   trimmed distance: its nearest 80 % of rows) and by distance; the best few refined by
//   Levenberg-Marquardt on the whitened residual (first robust: Huber-weighted rows; then plain
//   least squares) with forward-difference Jacobians over 1 % of each range (smaller increments
//   read the model's fine structure and creep); then a (1+1) evolution strategy from the nearest
//   member. A size with its direction (an offset and its angle, a phase) is fitted as the vector's
//   two components. Parameters stay in their ranges. d_F is the least distance of ANY member the
//   search evaluated: a member's distance is exact, only the search is not, so a fit that misses
//   the true minimum OVERSTATES d_F and never excuses a miss wrongly (it may call an unidentifiable
//   truth identifiable, never the reverse). d_F <= the detection d: every family holds the
//   no-effect member, whose distance is |s_E|.
// - The model's moments step where int(qN/4) steps (torque, misalignment): near a member of the
//   same physics the distance falls to a narrow cusp (rows crossing a step on one side only), which
//   the robust weights and the evolution strategy are there for; a cusp not reached leaves d
//   overstated.
// - Cost: on records longer than max_rows the fit reads every k-th row (at most 2,000 in zoo.cc),
//   the noise whitened by an autoregression fitted to the thinned noise, and d_F is scaled to the
//   full record by the detection d on all rows over the detection d on the thinned rows. That
//   ratio is exact for white noise and a residual shaped like s_E; an approximation otherwise (a
//   residual richer in fast components than s_E gains more from the full record than the ratio
//   says, one slower gains less): this one may err either way.
// - Gaussian, stationary noise, as oracle.h: an indication, not a proof, for spikes, steps and a
//   variance that moves.
#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "core/coupling_model.h"
#include "tests/diagnosis/zoo/channels.h"
#include "tests/diagnosis/zoo/hidden_effects.h"

namespace gc::zoo {

/// A family of signals on the rows the oracle reads (both channels, one value a row).
struct SignalFamily {
  std::string name;
  std::vector<EffectParameter> parameters;  ///< ranges (lo == hi: held) and typical sizes
  std::vector<double> none;                 ///< a member with (about) no signal; a start point
  std::vector<int> size_parameters;         ///< parameters the signal is about proportional to, together
  /// The signal at theta on the rows, into y and z (each set to the rows' count).
  std::function<void(const std::vector<double>& theta, std::vector<double>& y, std::vector<double>& z)> signal;
  std::function<void(std::vector<double>& theta)> project;  ///< optional: back into the physical set
};

struct IdentityOptions {
  int starts = 24;       ///< start points drawn over the ranges (besides `none`)
  int refined = 3;       ///< the best this many by each ranking (shape, distance) refined, each once
  int iterations = 8;    ///< Levenberg-Marquardt iterations (Jacobians) per refined start and kind, at most
  int polish = 100;      ///< the evolution strategy's evaluations, at most, each of its two runs
  std::uint64_t seed = 1;  ///< the start points' stream (derive_seed by the family's name)
};

struct RivalDistance {
  std::string name;
  double d = std::numeric_limits<double>::quiet_NaN();  ///< d_F, scaled to the full record
  std::vector<double> theta;                             ///< the nearest member found
  int evaluations = 0;                                   ///< signals computed
};

struct IdentityBound {
  double d = std::numeric_limits<double>::quiet_NaN();      ///< d_identity (the nearest rival's d_F)
  double power = std::numeric_limits<double>::quiet_NaN();  ///< Phi(d - z_0.01)
  std::string rival;                                        ///< the nearest rival; empty without one
  double detection_thinned_d = std::numeric_limits<double>::quiet_NaN();  ///< |s_E| on the rows read
  double scale = 1.0;              ///< full-record detection d / detection_thinned_d
  std::vector<RivalDistance> rivals;  ///< every rival, in the order given
};

/// The identity bound of signal s_E against `rivals` on the rows read: signal_* and noise_* there
/// (one length >= 64, finite; std::invalid_argument otherwise); full_detection_d the detection d on
/// all rows (oracle_bound), NaN to take the rows read as the record (scale 1). Without rivals, or
/// where a channel has no noise, d is NaN.
IdentityBound identity_bound(const std::vector<double>& signal_y, const std::vector<double>& signal_z,
                             const std::vector<double>& noise_y, const std::vector<double>& noise_z, double full_detection_d,
                             const std::vector<SignalFamily>& rivals, const IdentityOptions& options = {});

/// Every k-th of n rows, k the least giving at most max_rows (all rows when n <= max_rows).
std::vector<std::size_t> thinned_rows(std::size_t n, std::size_t max_rows);

/// The rivals of truth `name` (see above), in hidden_effect_table()'s order.
std::vector<std::string> identity_rivals(const std::string& name);

/// A truth's family as signals on rows `rows` of the effect-free truth `clean`: the family's
/// moments less clean's (a row the model refuses: no change, as the generator leaves it). A size
/// and its direction (HiddenEffectFamily::polar_angle) are fitted as the vector's two components,
/// its length within the size's range. The family holds references to model and clean.
SignalFamily signal_family(const std::string& name, const CouplingModel& model, double jam_rad, const Channels& clean,
                           std::vector<std::size_t> rows);

}  // namespace gc::zoo
