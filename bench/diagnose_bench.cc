// diagnose over 100,000 samples with the whole library, the refinements of the model's own
// effects and the discrepancy stage (issue 8: under 5 s on the 2-core machine). Recordings: the
// paper's applied-moment sweeps (diagnosis/synthesis) for the upwind coupling, 2 kN·m of noise, from
// the paper's model plus one hidden effect (the search runs twice: finds it, then finds noise),
// plus a moment only a formula explains (formula, then noise), or plus structure in time (issue
// 22): a 3.7 s interference, a step of one channel, a 0.3 s skew of the moment channels.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>

#include "core/coupling_geometry.h"
#include "diagnosis/diagnose.h"
#include "core/effects/effect_registry.h"
#include "core/effects/expression.h"
#include "diagnosis/synthesis/load_sequence.h"
#include "diagnosis/synthesis/synthesize.h"
#include "parallel/thread_parallel_for.h"
#include "tests/core/nrel_couplings.h"

namespace gc {
namespace {

CouplingModel paper_model() {
  return CouplingModel(testing::nrel_upwind(), {make_effect("friction"), make_effect("pressure_angle_rotation"),
                                                make_effect("self_weight")});
}

std::vector<RecordedSample> recording(const CouplingModel& truth, std::size_t samples) {
  LoadSequenceOptions options;
  options.samples = static_cast<int>(samples);
  options.jam_angle_rad = truth.geometry().jam_angle().angle_rad;
  options.direction_rad = 0.3;
  return synthesize(truth, load_sequence(options), {2000.0, 7}).samples;
}

void run(benchmark::State& state, const std::vector<RecordedSample>& data, std::size_t expected_rounds) {
  const CouplingModel model = paper_model();
  const ParallelFor parallel = thread_parallel_for();
  for (auto _ : state) {
    const Diagnosis d = diagnose(model, data, parallel);
    if (d.rounds.size() != expected_rounds) state.SkipWithError(d.summary.c_str());
    benchmark::DoNotOptimize(d.rounds.size());
    double evaluations = 0.0;
    for (const CandidateScore& c : d.rounds.front().ranking) evaluations += c.evaluations;
    state.counters["evaluations_per_candidate"] = evaluations / std::max<std::size_t>(1, d.rounds.front().ranking.size());
  }
  state.counters["samples"] = static_cast<double>(data.size());
}

void BM_DiagnoseHiddenHysteresis100k(benchmark::State& state) {
  static const auto data = recording(paper_model().with_effect(make_effect("hysteresis", {{"lag_rad", 0.0006}})), 100000);
  run(state, data, 2);
}

// Issue 22's terms in time: each found on the dense rows, then noise.
void BM_DiagnoseInterference100k(benchmark::State& state) {
  static const auto data = [] {
    auto samples = recording(paper_model(), 100000);
    for (RecordedSample& s : samples) s.measured.z_nm += 8000.0 * std::sin(2 * M_PI * s.input.time_s / 3.7);
    return samples;
  }();
  run(state, data, 2);
}

void BM_DiagnoseStep100k(benchmark::State& state) {
  static const auto data = [] {
    auto samples = recording(paper_model(), 100000);
    const double at = 0.4 * samples.back().input.time_s;
    for (RecordedSample& s : samples) if (s.input.time_s >= at) s.measured.y_nm += 6000.0;
    return samples;
  }();
  run(state, data, 2);
}

void BM_DiagnoseSkew100k(benchmark::State& state) {
  static const auto data = recording(paper_model().with_effect(make_effect("moment_delay", {{"delay_s", 0.3}})), 100000);
  run(state, data, 2);
}

void BM_DiagnoseFormula100k(benchmark::State& state) {
  static const auto data = recording(
      paper_model().with_effect(make_expression({{"travel_sign_along_misalignment", 6000.0}})), 100000);
  run(state, data, 2);
}

BENCHMARK(BM_DiagnoseHiddenHysteresis100k)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();
BENCHMARK(BM_DiagnoseFormula100k)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();
BENCHMARK(BM_DiagnoseInterference100k)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();
BENCHMARK(BM_DiagnoseStep100k)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();
BENCHMARK(BM_DiagnoseSkew100k)->Unit(benchmark::kSecond)->Iterations(1)->UseRealTime();

}  // namespace
}  // namespace gc

BENCHMARK_MAIN();
