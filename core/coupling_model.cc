#include "core/coupling_model.h"

#include <algorithm>
#include <limits>

#include "core/coupling_frame.h"
#include "core/effects/summed_input_timing.h"
#include "core/induced_moments.h"
#include "core/model_error.h"
#include "core/restoring_torque.h"

namespace gc {
namespace {

CouplingDefinition adjusted(CouplingDefinition coupling,
                            const std::vector<std::shared_ptr<const Effect>>& effects) {
  for (const auto& effect : effects) effect->adjust_coupling(coupling);
  return coupling;
}

}  // namespace

CouplingModel::CouplingModel(const CouplingDefinition& coupling,
                             std::vector<std::shared_ptr<const Effect>> effects,
                             const ContactOptions& options)
    : base_coupling_(coupling),
      effects_(std::move(effects)),
      options_(options),
      geometry_(adjusted(coupling, effects_)),
      restoring_torque_nm_(restoring_torque(geometry_).torque_nm),
      self_weight_moment_nm_(self_weight_moment_nm(geometry_)) {
  for (std::size_t i = 0; i < effects_.size(); ++i) {
    if (!effects_[i]) throw InvalidInput("effects", "a null effect");
    for (std::size_t k = 0; k < i; ++k) {
      if (effects_[k]->name() == effects_[i]->name()) {
        throw InvalidInput("effects." + effects_[i]->name(), "appears twice in one model");
      }
    }
    times_inputs_ = times_inputs_ || effects_[i]->times_inputs();
    reads_history_ = reads_history_ || effects_[i]->reads_history();
  }
}

InputTiming CouplingModel::input_timing(const MeasurementSample& sample) const {
  return summed_input_timing(effects_, sample);
}

InputReach CouplingModel::input_reach(const MeasurementSample& sample) const {
  InputReach reach;
  if (times_inputs_) {
    // timed_input reads from t - delay_s - average_s to t - delay_s.
    const InputTiming timing = input_timing(sample);
    reach.before_s = std::max(0.0, timing.delay_s + timing.average_s);
    reach.after_s = std::max(0.0, -timing.delay_s);
  }
  if (reads_history_) {
    for (const auto& effect : effects_) reach.before_s = std::max(reach.before_s, effect->history_s());
  }
  return reach;
}

ModelPrediction CouplingModel::with_history(ModelPrediction prediction, const InputHistory& history) const {
  if (!reads_history_) return prediction;
  for (const auto& effect : effects_) effect->adjust_outputs_in_history(history, prediction.moments);
  return prediction;
}

ModelPrediction CouplingModel::predict_timed(std::span<const RecordedSample> recording, std::size_t i,
                                             const WindowColumns* columns) const {
  if (!times_inputs_) return predict(recording[i].input);
  const InputTiming timing = input_timing(recording[i].input);
  return predict(timing.none() ? recording[i].input : timed_input(recording, i, timing, columns));
}

std::optional<WindowColumns> CouplingModel::window_columns(std::span<const RecordedSample> recording,
                                                                 std::span<const std::size_t> rows) const {
  if (!times_inputs_ || rows.empty() || recording.size() < 2) return std::nullopt;
  const double duration = recording.back().input.time_s - recording.front().input.time_s;
  if (!(duration > 0.0)) return std::nullopt;
  const double per_second = static_cast<double>(recording.size() - 1) / duration;  // samples [1/s]
  double from = std::numeric_limits<double>::infinity(), to = -from, in_windows = 0.0;
  for (const std::size_t i : rows) {
    const InputTiming timing = input_timing(recording[i].input);
    if (!(timing.average_s > 0.0)) continue;
    const double end = recording[i].input.time_s - timing.delay_s;
    from = std::min(from, end - timing.average_s);
    to = std::max(to, end);
    in_windows += timing.average_s * per_second;
  }
  if (!(to >= from) || in_windows <= 2.0 * ((to - from) * per_second + 1.0)) return std::nullopt;
  // The samples from the first at or after `from` to the last at or before `to`, in time order as
  // timed_input reads them (a recording out of order only finds a smaller table, and its windows
  // compute what the table lacks).
  std::size_t first = 0;
  while (first + 1 < recording.size() && recording[first].input.time_s < from) ++first;
  std::size_t last = first;
  while (last + 1 < recording.size() && recording[last + 1].input.time_s <= to) ++last;
  return WindowColumns(recording, first, last);
}

ModelPrediction CouplingModel::predict_at(std::span<const RecordedSample> recording, std::size_t i) const {
  return with_history(predict_timed(recording, i), {recording, i});
}

ModelPrediction CouplingModel::predict_at(std::span<const MeasurementSample> sequence, std::size_t i) const {
  if (!times_inputs_) return with_history(predict(sequence[i]), {sequence, i});
  const InputTiming timing = input_timing(sequence[i]);
  return with_history(predict(timing.none() ? sequence[i] : timed_input(sequence, i, timing)), {sequence, i});
}

CouplingModel::MomentsAtRows CouplingModel::moments_at(std::span<const RecordedSample> recording,
                                                      std::span<const std::size_t> rows) const {
  MomentsAtRows out;
  out.moments.resize(rows.size());
  out.errors.resize(rows.size());
  out.fields.resize(rows.size());
  std::vector<std::size_t> predicted;  // positions k of rows the model took
  const std::optional<WindowColumns> columns = window_columns(recording, rows);
  for (std::size_t k = 0; k < rows.size(); ++k) {
    try {
      out.moments[k] = predict_timed(recording, rows[k], columns ? &*columns : nullptr).moments;
      predicted.push_back(k);
    } catch (const InvalidInput& e) {
      out.errors[k] = e.what();
      out.fields[k] = e.field();
    } catch (const ModelError& e) {
      out.errors[k] = e.what();
    }
  }
  if (!reads_history_ || predicted.empty()) return out;
  std::vector<std::size_t> at(predicted.size());
  std::vector<SensorMoments> moments(predicted.size());
  for (std::size_t j = 0; j < predicted.size(); ++j) {
    at[j] = rows[predicted[j]];
    moments[j] = out.moments[predicted[j]];
  }
  for (const auto& effect : effects_) effect->adjust_outputs_in_history_at(recording, at, moments);
  for (std::size_t j = 0; j < predicted.size(); ++j) out.moments[predicted[j]] = moments[j];
  return out;
}

bool CouplingModel::has_effect(const std::string& name) const {
  return std::any_of(effects_.begin(), effects_.end(),
                     [&name](const auto& effect) { return effect->name() == name; });
}

CouplingModel CouplingModel::with_effect(std::shared_ptr<const Effect> effect) const {
  // Several effects fitted as one go in as themselves (core/effects/joint_effect.h).
  if (const auto members = effect->members(); !members.empty()) {
    CouplingModel out = *this;
    for (const auto& m : members) out = out.with_effect(m);
    return out;
  }
  std::vector<std::shared_ptr<const Effect>> effects;
  for (const auto& existing : effects_) {
    if (existing->name() != effect->name()) effects.push_back(existing);
  }
  effects.push_back(std::move(effect));
  // A formula (the expression effect) is defined on the model's moments before it: it stays last.
  std::stable_partition(effects.begin(), effects.end(), [](const auto& e) { return e->name() != "expression"; });
  return CouplingModel(base_coupling_, std::move(effects), options_);
}

CouplingModel CouplingModel::without_effect(const std::string& name) const {
  std::vector<std::shared_ptr<const Effect>> effects;
  for (const auto& existing : effects_) {
    if (existing->name() != name) effects.push_back(existing);
  }
  return CouplingModel(base_coupling_, std::move(effects), options_);
}

std::shared_ptr<const Effect> CouplingModel::effect(const std::string& name) const {
  for (const auto& existing : effects_) {
    if (existing->name() == name) return existing;
  }
  return nullptr;
}

ModelPrediction CouplingModel::predict(const MeasurementSample& sample) const {
  const ModelContext context{geometry_, restoring_torque_nm_, self_weight_moment_nm_};
  ModelPrediction prediction;
  ModelState& state = prediction.state;
  state.point = {sample.torque_nm, sample.misalignment_rad, sample.direction_rad, 0.0};
  state.contact = options_;
  for (const auto& effect : effects_) effect->adjust_inputs(sample, context, state);

  // The moments alone: a recording's diagnosis predicts millions of samples, and the per-tooth
  // report of tooth_contact() (zones, stress) is not part of them.
  const QuarterSums moments = double_prime_moments(geometry_, state.point, state.contact);
  // Eqs 44-47 with the frame shift the effects chose (phi with pressure_angle_rotation on).
  const Eigen::Vector2d global =
      double_prime_to_coupling(state.frame_shift_rad, state.point.direction_rad) *
      Eigen::Vector2d(moments.moment_y_dd_nm, moments.moment_z_dd_nm);
  prediction.moments = {global.x(), global.y()};
  for (const auto& effect : effects_) {
    effect->adjust_outputs(sample, context, state, prediction.moments);
  }
  return prediction;
}

}  // namespace gc
