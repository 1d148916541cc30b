// The moment channels lag the inputs: a DAQ that samples the bending bridges through another card or
// filter than the torque and misalignment channels records M(t - tau) beside T(t), zeta(t) (a skew),
// and a demodulator that averages the rotating bridges over N shaft revolutions records their mean
// over the last N * 60 / n seconds at a speed n [rpm]. A property of the recording's time axis: a
// model predicting a recording takes the inputs from it at that time (core/input_timing.h). A
// sample seen alone (the live monitor, sample by sample) is set back to first order instead,
// M(t - tau) = M(T - tau dT/dt, zeta - tau dzeta/dt), along the input rates the reader derives
// (core/input_rate.h), an average over a window counting as a delay of half of it.
#include <algorithm>
#include <cmath>

#include "core/coupling_geometry.h"
#include "core/effects/registration.h"

namespace gc {
namespace {

const EffectInfo kInfo{
    "moment_delay",
    "The moment channels lag the inputs: a skew between DAQ channels or a filter's group delay (a time), "
    "or a demodulator averaging the rotating bridges over shaft revolutions.",
    "Section 3 (instrumentation: moments from strain-gauge bridges on the rotating shaft, via telemetry)",
    {{"delay_s", "s", "tau, how long after the inputs the moments are recorded (negative: before)", -2.0, 5.0,
      0.0, 0.0, {-1.0, 1.0}, false, 0.0, "the time alignment of the DAQ channels (sample clocks, filters, buffers)"},
     {"averaging_revolutions", "-", "N, the moments are the mean over the last N shaft revolutions", 0.0, 10.0, 0.0,
      0.0, {0.0, 2.0}, false, 0.0, "the demodulation or averaging of the rotating bridges"}}};

/// Below this speed a revolution-locked average is not defined [rpm].
constexpr double kSlowestSpeedRpm = 0.1;

class MomentDelay final : public Effect {
 public:
  explicit MomentDelay(const ParameterValues& values)
      : Effect(kInfo, values), delay_s_(value("delay_s")), revolutions_(value("averaging_revolutions")) {}

  bool times_inputs() const override { return !neutral(); }

  InputTiming input_timing(const MeasurementSample& sample) const override {
    double average = 0.0;
    if (revolutions_ > 0.0 && sample.speed_rpm && std::abs(*sample.speed_rpm) > kSlowestSpeedRpm) {
      average = revolutions_ * 60.0 / std::abs(*sample.speed_rpm);
    }
    return {delay_s_, average};
  }

  void adjust_inputs(const MeasurementSample& sample, const ModelContext& context, ModelState& state) const override {
    if (sample.inputs_timed) return;  // taken from the recording at the right time already
    const InputTiming timing = input_timing(sample);
    const double tau = timing.delay_s + 0.5 * timing.average_s;
    if (tau == 0.0) return;
    OperatingPoint& p = state.point;
    // Clamped so that a large lag on a steep ramp never asks the model for a torque of the other
    // sign or a misalignment beyond the jam angle (eq 35): the first-order step is then cut short.
    if (sample.torque_rate_nm_s) p.torque_nm = std::max(p.torque_nm - tau * *sample.torque_rate_nm_s, 0.1 * p.torque_nm);
    if (sample.misalignment_rate_rad_s) {
      const double jam = context.geometry.jam_angle().angle_rad;
      const double back = std::max(p.misalignment_rad - tau * *sample.misalignment_rate_rad_s, 0.0);
      if (back < jam || back <= p.misalignment_rad) p.misalignment_rad = back;
    }
  }

 private:
  double delay_s_, revolutions_;
};

}  // namespace

EffectRegistration moment_delay_effect() { return register_effect<MomentDelay>(kInfo); }

}  // namespace gc
