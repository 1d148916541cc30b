// The model a recording is compared with: a coupling and an ordered list of effects around the
// paper's tooth contact and induced moments (docs/effects.md). The paper's model is the
// configuration {friction, pressure_angle_rotation, self_weight} (data/models/paper.textproto).
#pragma once

#include <cstddef>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/coupling_geometry.h"
#include "core/effects/effect.h"
#include "core/input_timing.h"
#include "core/recorded_sample.h"

namespace gc {

/// One prediction, with the inputs the calculation saw after the effects.
struct ModelPrediction {
  SensorMoments moments;   ///< M_sy', M_sz' [N·m]
  ModelState state;        ///< T, zeta, beta, mu, options after the effects
};

/// The stretch of a recording around a sample's time t that predict_at reads: every sample in
/// [t - before_s, t + after_s], and beyond each end the nearest one.
struct InputReach {
  double before_s = 0.0;
  double after_s = 0.0;
};

class CouplingModel {
 public:
  /// Applies the effects' coupling adjustments and builds the geometry (throws InvalidInput).
  /// Effects act in the given order; at most one effect of each name.
  CouplingModel(const CouplingDefinition& coupling,
                std::vector<std::shared_ptr<const Effect>> effects,
                const ContactOptions& options = {});

  const CouplingGeometry& geometry() const { return geometry_; }
  const CouplingDefinition& base_coupling() const { return base_coupling_; }
  const std::vector<std::shared_ptr<const Effect>>& effects() const { return effects_; }
  const ContactOptions& options() const { return options_; }
  bool has_effect(const std::string& name) const;

  /// This model with `effect` appended (or replacing the one of the same name).
  CouplingModel with_effect(std::shared_ptr<const Effect> effect) const;
  /// This model without the effect of that name (unchanged when it has none).
  CouplingModel without_effect(const std::string& name) const;
  /// The effect of that name, nullptr when the model has none.
  std::shared_ptr<const Effect> effect(const std::string& name) const;

  /// Sensor moments for one measured sample: effects on the inputs, eqs 5-47 through the
  /// z'' frame turned by the state's frame shift plus beta, effects on the outputs. Throws
  /// InvalidInput (e.g. the effective misalignment at or beyond the jam angle).
  ModelPrediction predict(const MeasurementSample& sample) const;

  /// Sample i of a recording or an input sequence (time order): predict() on its inputs as the
  /// moment channels see them, taken from the sequence at the time the effects say
  /// (core/input_timing.h, e.g. moment_delay), then the outputs that depend on the inputs before
  /// sample i (Effect::adjust_outputs_in_history, e.g. a formula's ringing terms);
  /// predict(sequence[i]) for a model without such effects.
  ModelPrediction predict_at(std::span<const RecordedSample> recording, std::size_t i) const;
  ModelPrediction predict_at(std::span<const MeasurementSample> sequence, std::size_t i) const;
  /// predict_at's moments at each of `rows` of a recording (any order; in time order they share
  /// the effects' passes over the history, Effect::adjust_outputs_in_history_at): the same numbers,
  /// to the bit. A row the model refuses (ModelError) has its message and no moments.
  struct MomentsAtRows {
    std::vector<SensorMoments> moments;  ///< M_sy', M_sz' at rows[k] [N·m]; zero where errors[k] is set
    std::vector<std::string> errors;     ///< why the model refused rows[k]; empty where it was predicted
    std::vector<std::string> fields;     ///< the input it refused (InvalidInput::field); empty for others
  };
  MomentsAtRows moments_at(std::span<const RecordedSample> recording, std::span<const std::size_t> rows) const;
  /// What moments_at reads the averaging windows of `rows` from (core/input_timing.h): the columns
  /// of the samples they span, when those windows hold more than twice as many samples in all (the
  /// columns then cost less than a sine and a cosine of each sample of each window); none otherwise.
  std::optional<WindowColumns> window_columns(std::span<const RecordedSample> recording,
                                              std::span<const std::size_t> rows) const;
  /// The sum of the effects' input timings at this sample.
  InputTiming input_timing(const MeasurementSample& sample) const;
  /// Whether predict_at(recording, i) reads samples other than i (an effect times the inputs or
  /// reads their history): a caller that changes a recording's other rows must then keep them.
  bool reads_other_samples() const { return times_inputs_ || reads_history_; }
  /// What predict_at reads of a recording around this sample: the input timing's delay and
  /// average (a negative delay reads ahead) and the effects' history_s. A caller holding a
  /// recording in pieces (validate's chunks) keeps that much of the pieces beside it.
  InputReach input_reach(const MeasurementSample& sample) const;

 private:
  CouplingDefinition base_coupling_;
  std::vector<std::shared_ptr<const Effect>> effects_;
  ContactOptions options_;
  CouplingGeometry geometry_;
  double restoring_torque_nm_;
  double self_weight_moment_nm_;
  bool times_inputs_ = false;  ///< some effect times the inputs (predict_at looks them up)
  bool reads_history_ = false;  ///< some effect's outputs depend on the inputs before the sample

  /// predict() on sample i's inputs as the moment channels see them (the effects' input timing),
  /// its averaging window read from `columns` where they hold it.
  ModelPrediction predict_timed(std::span<const RecordedSample> recording, std::size_t i,
                                const WindowColumns* columns = nullptr) const;
  /// The effects' adjust_outputs_in_history on `prediction`.
  ModelPrediction with_history(ModelPrediction prediction, const InputHistory& history) const;
};

}  // namespace gc
