// Several effects refitted as one: their parameters together, each named
// "<effect>.<parameter>", so that one fit moves them jointly. Two effects fitted one after the
// other trade with each other (a thermal misalignment fitted beside an unexplained weight offset
// takes a share of it, and refitting them in turn creeps toward the truth a round at a time);
// fitted together they find it at once.
//
// A joint effect is a fitting device, not a part of a model: CouplingModel::with_effect puts its
// members in place of the model's effects of their names (Effect::members), so a model, its file
// and its report only ever hold the members.
#pragma once

#include <memory>
#include <vector>

#include "core/effects/effect.h"
#include "core/effects/effect_registry.h"

namespace gc {

class JointEffect final : public Effect {
 public:
  /// `values` by "<effect>.<parameter>" (omitted ones at their defaults), split among `members`.
  /// Throws InvalidInput as each member's registration does for its values.
  JointEffect(const EffectInfo& info, const ParameterValues& values, const std::vector<EffectRegistration>& members);

  std::vector<std::shared_ptr<const Effect>> members() const override { return members_; }

  // Were one put in a model directly, its members would act in order.
  void adjust_coupling(CouplingDefinition& coupling) const override;
  void adjust_inputs(const MeasurementSample& sample, const ModelContext& context, ModelState& state) const override;
  void adjust_outputs(const MeasurementSample& sample, const ModelContext& context, const ModelState& state,
                      SensorMoments& moments) const override;
  void adjust_outputs_in_history(const InputHistory& history, SensorMoments& moments) const override;
  void adjust_outputs_in_history_at(std::span<const RecordedSample> recording, std::span<const std::size_t> rows,
                                    std::span<SensorMoments> moments) const override;
  bool reads_history() const override;
  double history_s() const override;
  /// The members' timings summed (summed_input_timing.h).
  InputTiming input_timing(const MeasurementSample& sample) const override;
  bool times_inputs() const override;

 private:
  std::vector<std::shared_ptr<const Effect>> members_;
};

/// The registration of `members` (at least two, none itself joint, no name twice) fitted as one.
/// Its info is named "<a>+<b>..." and lists every member's parameters, prefixed; it is made once
/// per list of names and lives as long as the process. Throws InvalidInput otherwise.
EffectRegistration joint_registration(const std::vector<EffectRegistration>& members);

/// The joint values of `effects` (as joint_registration's info names them).
ParameterValues joint_values(const std::vector<std::shared_ptr<const Effect>>& effects);

}  // namespace gc
