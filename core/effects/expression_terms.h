// The terms a formula for the model's discrepancy is built from (docs/diagnosis.md, "formula").
// Each term is a physical quantity the model knows times a direction on the two sensor channels:
//   term(sample) = s(sample) * d(sample),   s a scalar with a unit, d a unit 2-vector (M_sy', M_sz'),
// so that "a moment along the model's moment direction, proportional to T zeta" is one term and
// its coefficient has a unit (N·m per unit of s). A few terms take the model's own moments instead
// (gain and cross-talk), and the rotation phase gives the once-per-revolution harmonics. A slow
// cycle in time (a zero that swings with the cell's temperature control) is a term whose period is
// part of its name: time_cycle_<P>s_<sin|cos>_on_<y|z>. The rig's own vocabulary is made for a
// coupling and a recording the same way: the tooth-mesh order of a coupling of N teeth and its
// sidebands (mesh_order_<N>[_plus_<j>|_minus_<j>]_..., shaft orders N, N +- j), and a mode of the
// rig ringing after a change of the torque (ringing_<f_n>Hz_zeta<zeta>_on_<y|z>,
// core/effects/ringing_response.h), whose value at a sample depends on the torque's history.
// The same catalogue serves the discrepancy search and the `expression` effect that adds a found
// formula to a model file, so what was fitted is what is added.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Dense>

#include "core/effects/ringing_response.h"
#include "core/input_history.h"
#include "core/measurement_sample.h"

namespace gc {

struct ExpressionTerm {
  std::string name;              ///< e.g. "travel_sign_along_misalignment"
  std::string formula;           ///< e.g. "sign(dzeta/dt) (cos beta, sin beta)"
  std::string coefficient_unit;  ///< e.g. "N·m"
  double bound = 0.0;            ///< |coefficient| at most this [coefficient_unit]
  std::string mechanisms;        ///< what such a term usually means, one sentence
  /// The term's (M_sy', M_sz') per unit coefficient for a sample and the model's moments there
  /// [N·m per coefficient unit]; nullopt when the sample lacks the input (speed, temperature, phase).
  /// A term of the history (reads_history()) is zero here: a sample alone is at steady state.
  std::optional<Eigen::Vector2d> value(const MeasurementSample& sample, const SensorMoments& model) const;
  /// True for a term whose value depends on the inputs before the sample (a ringing mode).
  bool reads_history() const { return ringing.natural_frequency_hz > 0.0; }
  /// Its value at the history's sample [N·m per coefficient unit]; zero for the others.
  Eigen::Vector2d history_value(const InputHistory& history) const;
  /// history_value at each of `rows` of `recording` (time order), in one pass a block of time
  /// (torque_ringing_at_rows): the same numbers, to the bit [N·m per coefficient unit].
  std::vector<double> history_values_at(std::span<const RecordedSample> recording,
                                        std::span<const std::size_t> rows) const;
  /// How far back history_value reads [s] (ringing_history_s); 0 for the others.
  double history_s() const { return reads_history() ? ringing_history_s(ringing) : 0.0; }
  /// The channel it acts on: (1, 0) on M_sy', (0, 1) on M_sz'; zero for the others.
  Eigen::Vector2d history_channel() const;
  /// The frequency the term oscillates at, at this sample [Hz]: k n / 60 for shaft order k, 1 / P
  /// for a cycle, f_n for a ringing mode; 0 for a term that does not oscillate (or lacks the speed).
  /// A term above the Nyquist frequency of the rows it is fitted on is not offered there.
  double frequency_hz(const MeasurementSample& sample) const;

  // What the term is made of (see expression_terms.cc).
  int scalar = 0;
  int frame = 0;
  double period_s = 0.0;  ///< of a time_cycle term [s]; 0 for the others
  int order = 0;          ///< of a shaft-order term (k of sin/cos(k phi_rot)); 0 for the others
  double step_time_s = 0.0;  ///< of a step term [s]
  /// What scales a shaft-order term's amplitude: none, the torque (a ripple that grows with the load
  /// the teeth share), or the speed squared (an unbalance's centrifugal force).
  enum class Modulation { none, torque, speed_squared } modulation = Modulation::none;
  RingingMode ringing = {};  ///< of a ringing term; f_n = 0 for the others
};

/// Every term, in a fixed order.
const std::vector<ExpressionTerm>& expression_terms();
/// nullptr when no term has that name. A time_cycle term (a period of 0.02 s to 1e6 s, written
/// with at most 6 significant digits) or a step term (a time within +-1e9 s, likewise) is made on
/// first use and lives as long as the process.
const ExpressionTerm* find_expression_term(std::string_view name);

/// The term `name` as find_expression_term finds it, but a made-on-use one (time_cycle, step)
/// as a new object of the caller's, not interned: what a model holds for as long as it lives,
/// so that models from the network (live swaps) leave nothing behind (issue 38). nullopt for an
/// unknown name; a catalogue term is copied.
std::optional<ExpressionTerm> make_expression_term(std::string_view name);

/// The four time_cycle terms (sin and cos on each channel) of `period_s`, written with 6
/// significant digits: the phase of a cycle must hold over the whole recording (a 0.4 Hz
/// interference over 10,000 s needs the period to 1e-5 of itself).
std::vector<std::string> cycle_term_names(double period_s);

/// The two step terms (on each channel) of a step at `time_s`, written with 6 significant digits:
/// 0 before that time, 1 from it on.
std::vector<std::string> step_term_names(double time_s);

/// The tooth-mesh terms of a coupling of `teeth` teeth: shaft orders N (the mesh) and N +- 1, N +- 2
/// (its sidebands), each as sin/cos on one channel and as forward and backward whirls, plain and
/// growing with torque: "mesh_order_56_forward_cos", "torque_mesh_order_56_plus_1_sin_on_y".
std::vector<std::string> mesh_term_names(int teeth);
/// Sidebands offered either side of the mesh order: N +- 1 (once per revolution), N +- 2.
inline constexpr int kMeshSidebands = 2;

/// The two ringing terms (the torque's h * u - u on each channel) of a mode, its frequency and
/// damping written with 3 significant digits: "ringing_3.2Hz_zeta0.05_on_y".
std::vector<std::string> ringing_term_names(const RingingMode& mode);

/// Shaft orders offered beside the revolution (order 1): 2 (an oval sleeve, a bent shaft's second
/// harmonic) to this.
inline constexpr int kHighestShaftOrder = 4;

}  // namespace gc
