#include "tests/diagnosis/hidden_effect_scenarios.h"

#include "core/coupling_geometry.h"
#include "parallel/thread_parallel_for.h"

namespace gc::testing {

std::vector<MeasurementSample> paper_sequence(const CouplingDefinition& coupling, LoadSequenceKind kind) {
  LoadSequenceOptions options;
  options.kind = kind;
  options.samples = 960;
  options.sample_period_s = 0.1;
  options.jam_angle_rad = CouplingGeometry(coupling).jam_angle().angle_rad;
  options.direction_rad = 10.0 * M_PI / 180.0;
  std::vector<MeasurementSample> samples = load_sequence(options);
  options.direction_rad = 100.0 * M_PI / 180.0;
  for (MeasurementSample s : load_sequence(options)) {
    s.time_s += options.samples * options.sample_period_s;
    samples.push_back(s);
  }
  return samples;
}

std::vector<std::shared_ptr<const Effect>> paper_effects(const std::string& without) {
  std::vector<std::shared_ptr<const Effect>> effects;
  for (const std::string name : {"friction", "pressure_angle_rotation", "self_weight"}) {
    if (name != without) effects.push_back(make_effect(name));
  }
  return effects;
}

ParameterValues draw_parameters(const ParameterRanges& ranges, std::mt19937_64& random) {
  ParameterValues values;
  for (const auto& [name, range] : ranges) {
    values[name] = std::uniform_real_distribution<double>(range.first, range.second)(random);
  }
  return values;
}

Diagnosis diagnose_on_threads(const CouplingModel& model, const std::vector<RecordedSample>& observations) {
  return diagnose(model, observations, thread_parallel_for(2));
}

double best_reduction(const DiagnosisRound& round) {
  return round.ranking.empty() ? 0.0 : round.ranking.front().reduction;
}

}  // namespace gc::testing
