// The terms a formula for the model's discrepancy is built from (docs/diagnosis.md, "formula").
// Each term is a physical quantity the model knows times a direction on the two sensor channels:
//   term(sample) = s(sample) * d(sample),   s a scalar with a unit, d a unit 2-vector (M_sy', M_sz'),
// so that "a moment along the model's moment direction, proportional to T zeta" is one term and
// its coefficient has a unit (N·m per unit of s). A few terms take the model's own moments instead
// (gain and cross-talk), and the rotation phase gives the once-per-revolution harmonics. A slow
// cycle in time (a zero that swings with the cell's temperature control) is a term whose period is
// part of its name: time_cycle_<P>s_<sin|cos>_on_<y|z>.
// The same catalogue serves the discrepancy search and the `expression` effect that adds a found
// formula to a model file, so what was fitted is what is added.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Dense>

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
  std::optional<Eigen::Vector2d> value(const MeasurementSample& sample, const SensorMoments& model) const;

  // What the term is made of (see expression_terms.cc).
  int scalar = 0;
  int frame = 0;
  double period_s = 0.0;  ///< of a time_cycle term [s]; 0 for the others
  int order = 0;          ///< of a shaft-order term (k of sin/cos(k phi_rot)); 0 for the others
  double step_time_s = 0.0;  ///< of a step term [s]
  /// What scales a shaft-order term's amplitude: none, the torque (a ripple that grows with the load
  /// the teeth share), or the speed squared (an unbalance's centrifugal force).
  enum class Modulation { none, torque, speed_squared } modulation = Modulation::none;
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

/// Shaft orders offered beside the revolution (order 1): 2 (an oval sleeve, a bent shaft's second
/// harmonic) to this.
inline constexpr int kHighestShaftOrder = 4;

}  // namespace gc
