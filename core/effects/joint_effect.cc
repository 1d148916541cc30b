#include "core/effects/joint_effect.h"

#include <algorithm>

#include <map>
#include <mutex>
#include <set>

#include "core/effects/summed_input_timing.h"
#include "core/model_error.h"

namespace gc {
namespace {

constexpr char kSeparator = '.';

std::string joint_name(const std::vector<EffectRegistration>& members) {
  std::string name;
  for (const EffectRegistration& m : members) name += (name.empty() ? "" : "+") + m.info->name;
  return name;
}

EffectInfo make_info(const std::vector<EffectRegistration>& members) {
  EffectInfo info;
  info.name = joint_name(members);
  for (const EffectRegistration& m : members) {
    info.physics += (info.physics.empty() ? "" : " Together with: ") + m.info->physics;
    info.source += (info.source.empty() ? "" : "; ") + m.info->source;
    info.requires_inputs.insert(info.requires_inputs.end(), m.info->requires_inputs.begin(), m.info->requires_inputs.end());
    for (ParameterSpec spec : m.info->parameters) {
      spec.name = m.info->name + kSeparator + spec.name;
      info.parameters.push_back(std::move(spec));
    }
  }
  return info;
}

const EffectInfo& interned_info(const std::vector<EffectRegistration>& members) {
  static std::mutex mutex;
  static std::map<std::string, std::unique_ptr<const EffectInfo>> interned;
  std::lock_guard lock(mutex);
  auto& slot = interned[joint_name(members)];
  if (!slot) slot = std::make_unique<const EffectInfo>(make_info(members));
  return *slot;
}

}  // namespace

JointEffect::JointEffect(const EffectInfo& info, const ParameterValues& values,
                         const std::vector<EffectRegistration>& members)
    : Effect(info, values) {
  for (const EffectRegistration& m : members) {
    ParameterValues own;
    for (const ParameterSpec& spec : m.info->parameters) own[spec.name] = value(m.info->name + kSeparator + spec.name);
    members_.push_back(m.make(own));
  }
}

void JointEffect::adjust_coupling(CouplingDefinition& coupling) const {
  for (const auto& m : members_) m->adjust_coupling(coupling);
}

void JointEffect::adjust_inputs(const MeasurementSample& sample, const ModelContext& context, ModelState& state) const {
  for (const auto& m : members_) m->adjust_inputs(sample, context, state);
}

void JointEffect::adjust_outputs(const MeasurementSample& sample, const ModelContext& context, const ModelState& state,
                                 SensorMoments& moments) const {
  for (const auto& m : members_) m->adjust_outputs(sample, context, state, moments);
}

void JointEffect::adjust_outputs_in_history(const InputHistory& history, SensorMoments& moments) const {
  for (const auto& m : members_) m->adjust_outputs_in_history(history, moments);
}

void JointEffect::adjust_outputs_in_history_at(std::span<const RecordedSample> recording,
                                               std::span<const std::size_t> rows,
                                               std::span<SensorMoments> moments) const {
  for (const auto& m : members_) m->adjust_outputs_in_history_at(recording, rows, moments);
}

bool JointEffect::reads_history() const {
  return std::any_of(members_.begin(), members_.end(), [](const auto& m) { return m->reads_history(); });
}

double JointEffect::history_s() const {
  double longest = 0.0;
  for (const auto& m : members_) longest = std::max(longest, m->history_s());
  return longest;
}

InputTiming JointEffect::input_timing(const MeasurementSample& sample) const {
  return summed_input_timing(members_, sample);
}

bool JointEffect::times_inputs() const {
  return std::any_of(members_.begin(), members_.end(), [](const auto& m) { return m->times_inputs(); });
}

EffectRegistration joint_registration(const std::vector<EffectRegistration>& members) {
  std::set<std::string> names;
  for (const EffectRegistration& m : members) {
    if (!m.info || !names.insert(m.info->name).second || m.info->name.find('+') != std::string::npos) {
      throw InvalidInput("effects", "a joint fit takes distinct effects, none itself joint: " + joint_name(members));
    }
  }
  if (members.size() < 2) throw InvalidInput("effects", "a joint fit takes at least two effects: " + joint_name(members));
  const EffectInfo& info = interned_info(members);
  return {&info, [&info, members](const ParameterValues& values) -> std::shared_ptr<const Effect> {
            return std::make_shared<const JointEffect>(info, values, members);
          }};
}

ParameterValues joint_values(const std::vector<std::shared_ptr<const Effect>>& effects) {
  ParameterValues values;
  for (const auto& e : effects) {
    for (std::size_t i = 0; i < e->info().parameters.size(); ++i) {
      values[e->name() + kSeparator + e->info().parameters[i].name] = e->values()[i];
    }
  }
  return values;
}

}  // namespace gc
