#include "tests/diagnosis/independent/recording_inputs.h"

#include <numbers>
#include <cmath>

#include "core/coupling_geometry.h"
#include "core/loading_direction.h"
#include "tests/core/nrel_couplings.h"

namespace gc::independent {

std::vector<MeasurementSample> recording_inputs(LoadSequenceKind kind) {
  LoadSequenceOptions options;
  options.kind = kind;
  options.samples = 960;
  options.sample_period_s = 0.1;
  options.jam_angle_rad = CouplingGeometry(testing::nrel_upwind()).jam_angle().angle_rad;
  options.direction_rad = testing::deg(10);
  std::vector<MeasurementSample> samples = load_sequence(options);
  options.direction_rad = testing::deg(100);
  for (MeasurementSample s : load_sequence(options)) {
    s.time_s += options.samples * options.sample_period_s;
    samples.push_back(s);
  }
  const double pi = std::numbers::pi;
  const double end_s = samples.back().time_s;
  LoadingDirectionTracker loading(2e-5, 0.5);  // the inputs are noise-free: the smallest band
  double phase_rad = 0.0;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    MeasurementSample& s = samples[i];
    s.speed_rpm = 12.0 + 2.0 * std::sin(2.0 * pi * s.time_s / 23.0);
    if (i > 0) {  // trapezoidal integral of the angular speed [rad/s = rpm * 2 pi / 60]
      const double dt = s.time_s - samples[i - 1].time_s;
      phase_rad += 0.5 * (*s.speed_rpm + *samples[i - 1].speed_rpm) * 2.0 * pi / 60.0 * dt;
    }
    s.rotation_phase_rad = phase_rad;
    s.temperature_c = 35.0 + 20.0 * s.time_s / end_s + 1.5 * std::sin(2.0 * pi * s.time_s / 31.0);
    s.loading_direction = loading.next(s.time_s, s.misalignment_rad);
    s.travel_direction = loading.last_travel();  // as the recording reader derives it
  }
  return samples;
}

std::vector<int> travel_direction(const std::vector<MeasurementSample>& samples) {
  std::vector<int> travel(samples.size(), 0);
  int last = 0;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const std::size_t before = i == 0 ? 0 : i - 1;
    const std::size_t after = i + 1 < samples.size() ? i + 1 : i;
    const double change = samples[after].misalignment_rad - samples[before].misalignment_rad;
    if (change > 1e-6) last = 1;
    if (change < -1e-6) last = -1;
    travel[i] = last;
  }
  return travel;
}

}  // namespace gc::independent
