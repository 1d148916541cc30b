// A physical effect as a part of the model (docs/effects.md): a name, the physics it stands
// for, its parameters with units, bounds and neutral values, and how it changes the model's
// coupling, inputs or outputs. An effect holds parameter values only, never per-call state,
// so a model with effects stays reentrant.
#pragma once

#include <cmath>
#include <map>
#include <memory>
#include <span>
#include <string>
#include <vector>

#include "core/coupling_definition.h"
#include "core/input_history.h"
#include "core/input_timing.h"
#include "core/measurement_sample.h"
#include "core/operating_point.h"
#include "core/recorded_sample.h"
#include "core/tooth_contact.h"

namespace gc {

class CouplingGeometry;

/// The coupling quantity a plausible range is given in.
enum class RangeScale {
  absolute,   ///< the parameter's own unit
  jam_angle,  ///< fractions of the coupling's jam angle xi (eq 35)
};

/// Where a fitted value may end and still be called this physics (docs/effects.md gives the
/// source of each). The diagnosis searches in it first, widens toward the bounds when a fit
/// sits on its edge, and calls an effect fitted outside it "partly explains".
struct PlausibleRange {
  double lower = -INFINITY;  ///< [unit, or fraction of the scale]
  double upper = INFINITY;
  RangeScale scale = RangeScale::absolute;
};

struct ParameterSpec {
  std::string name;           ///< e.g. "mu0"
  std::string unit;           ///< SI unit, "-" for none
  std::string meaning;        ///< one line
  double lower = 0.0;         ///< physical bounds, inclusive
  double upper = 0.0;
  double neutral = 0.0;       ///< the value at which the effect does nothing
  double default_value = 0.0; ///< the value used when a configuration omits it
  PlausibleRange plausible;   ///< unbounded: every value within the bounds is plausible
  /// A shape parameter that diagnose holds at its default when it adds the effect, and frees only
  /// when it refines an effect the model already has: the effect's main parameters are found first,
  /// on the paper's form, and the shape then bends it (a free shape at the first fit trades with
  /// them and finds poorer optima).
  bool refine_only = false;
  /// > 0 for an angle (a direction, a phase) of this period [unit]: it wraps, so no value of it is
  /// on a bound or implausible. Its bounds span two periods, so that a fit can cross the seam at
  /// +-pi; the diagnosis reports it wrapped into (-period/2, period/2].
  double period = 0.0;
  /// What to check on the rig when a fitted value is outside the plausible range, e.g. "the
  /// alignment of the rig": plausibility is advice, never a veto (docs/diagnosis.md).
  std::string check = {};
  /// Where the effect's size crosses zero along an input (a temperature of alignment, a torque that
  /// centres the hub): the effect is an amplitude times (input - this), so its cost's valley is a
  /// hyperbola in the two (their product nearly fixed), along which Levenberg-Marquardt's straight
  /// steps crawl. Or a direction whose cost has valleys of its own (an assembly misalignment's: the
  /// steps of eqs 42-43). Diagnose fits the others at a grid of its values and starts from the best.
  bool profiled = false;
};

/// `value` wrapped into (-period/2, period/2] (unchanged for period <= 0).
double wrap_periodic(double value, double period);

/// The plausible range in the parameter's unit for a coupling of jam angle `jam_angle_rad`,
/// within the bounds.
std::pair<double, double> plausible_range(const ParameterSpec& spec, double jam_angle_rad);

/// A measured input that a recording may lack (core/measurement_sample.h's optionals).
enum class OptionalInput { speed, temperature, rotation_phase };

/// Whether `sample` has `input`.
bool has_input(const MeasurementSample& sample, OptionalInput input);

struct EffectInfo {
  std::string name;     ///< registry name, snake_case
  std::string physics;  ///< what it represents, one paragraph
  std::string source;   ///< where the paper discusses it
  std::vector<ParameterSpec> parameters;
  /// Inputs without which the effect changes nothing (a thermal growth without the oil
  /// temperature): on a recording that lacks one, fitting it is wasted work.
  std::vector<OptionalInput> requires_inputs = {};
};

using ParameterValues = std::map<std::string, double>;

/// What the model computes with for one sample; effects adjust it before the calculation.
struct ModelState {
  OperatingPoint point;          ///< T, zeta, beta, mu as the calculation will see them
  ContactOptions contact;        ///< eqs 14, 20-22 options and the spacing error
  double frame_shift_rad = 0.0;  ///< rotation of z'' from the misalignment axis (eqs 44-45)
};

/// Quantities of the coupling that effects read, computed once per model.
struct ModelContext {
  const CouplingGeometry& geometry;
  double restoring_torque_nm;     ///< eqs 49-53
  double self_weight_moment_nm;   ///< eq 48's weight term
};

class Effect {
 public:
  /// Fills omitted parameters with their defaults. Throws InvalidInput naming
  /// "effects.<name>.<parameter>" for an unknown parameter or a value outside its bounds.
  Effect(const EffectInfo& info, const ParameterValues& values);
  virtual ~Effect() = default;

  const EffectInfo& info() const { return info_; }
  const std::string& name() const { return info_.name; }
  /// Parameter values in the order of info().parameters.
  const std::vector<double>& values() const { return values_; }
  double value(const std::string& parameter) const;
  /// True when every parameter sits at its neutral value: the effect changes nothing. False for
  /// a switch without parameters (e.g. continuous_quarter_sums).
  bool neutral() const;

  /// Once, when the model is built (e.g. a stiffness factor).
  virtual void adjust_coupling(CouplingDefinition& /*coupling*/) const {}
  /// Per sample, before tooth contact and moments are computed.
  virtual void adjust_inputs(const MeasurementSample& /*sample*/, const ModelContext& /*context*/,
                             ModelState& /*state*/) const {}
  /// Per sample, on the moments at the sensors.
  virtual void adjust_outputs(const MeasurementSample& /*sample*/,
                              const ModelContext& /*context*/, const ModelState& /*state*/,
                              SensorMoments& /*moments*/) const {}
  /// Per sample of a sequence, after every effect's adjust_outputs, on the moments at the sensors,
  /// for an output that depends on the inputs before the sample (a mode of the rig ringing after a
  /// change of the load): predict_at calls it, predict() of a sample alone (at steady state) does not.
  virtual void adjust_outputs_in_history(const InputHistory& /*history*/, SensorMoments& /*moments*/) const {}
  /// adjust_outputs_in_history at each of `rows` (any order) of `recording` (in time order), on
  /// moments[k] for rows[k]: the same numbers, to the bit, with work shared between rows that come
  /// in time order where the effect can (a ringing's pass over a block of time). This default asks
  /// row by row.
  virtual void adjust_outputs_in_history_at(std::span<const RecordedSample> recording,
                                            std::span<const std::size_t> rows,
                                            std::span<SensorMoments> moments) const;
  /// True when adjust_outputs_in_history can change the moments.
  virtual bool reads_history() const { return false; }
  /// How far before a sample's time adjust_outputs_in_history reads the inputs [s] (and the one
  /// sample before that stretch); 0 when it reads none (CouplingModel::input_reach).
  virtual double history_s() const { return 0.0; }
  /// When the moment channels see the inputs of this sample (core/input_timing.h): a model
  /// predicting a recording takes the inputs from the recording at that time.
  virtual InputTiming input_timing(const MeasurementSample& /*sample*/) const { return {}; }
  /// True when input_timing can be other than none (a recording's evaluation then looks it up).
  virtual bool times_inputs() const { return false; }
  /// The effects this one stands for when it is several fitted as one (core/effects/joint_effect.h);
  /// empty for an effect that stands for itself.
  virtual std::vector<std::shared_ptr<const Effect>> members() const { return {}; }

 private:
  const EffectInfo& info_;
  std::vector<double> values_;
};

/// Adds the misalignment vector (zeta, beta) to the state's, in the plane of misalignment.
/// Shared by the effects that offset the measured misalignment.
void add_misalignment(double zeta_rad, double beta_rad, OperatingPoint& point);

}  // namespace gc
