// Gain and offset errors of the bending-moment channels (Section 3: "calibration forces were
// applied ... to determine the appropriate slopes and offsets for each of the bending
// channels"): M_measured = (1 + g) M + o, per channel.
#include "core/effects/registration.h"

namespace gc {
namespace {

const EffectInfo kInfo{
    "channel_gain_offset",
    "Calibration errors of the strain-gauge bending channels: a relative gain error and an "
    "offset on each of M_sy' and M_sz'.",
    "Section 3 (instrumentation and calibration)",
    {{"gain_y", "-", "relative gain error of M_sy'", -0.5, 0.5, 0.0, 0.0, {-0.1, 0.1}},
     {"gain_z", "-", "relative gain error of M_sz'", -0.5, 0.5, 0.0, 0.0, {-0.1, 0.1}},
     {"offset_y_nm", "N·m", "offset of M_sy'", -2e6, 2e6, 0.0, 0.0, {-2e5, 2e5}},
     {"offset_z_nm", "N·m", "offset of M_sz'", -2e6, 2e6, 0.0, 0.0, {-2e5, 2e5}}}};

class ChannelGainOffset final : public Effect {
 public:
  explicit ChannelGainOffset(const ParameterValues& values)
      : Effect(kInfo, values),
        gain_y_(value("gain_y")),
        gain_z_(value("gain_z")),
        offset_y_(value("offset_y_nm")),
        offset_z_(value("offset_z_nm")) {}

  void adjust_outputs(const MeasurementSample&, const ModelContext&, const ModelState&,
                      SensorMoments& moments) const override {
    moments.y_nm = (1.0 + gain_y_) * moments.y_nm + offset_y_;
    moments.z_nm = (1.0 + gain_z_) * moments.z_nm + offset_z_;
  }

 private:
  double gain_y_, gain_z_, offset_y_, offset_z_;
};

}  // namespace

EffectRegistration channel_gain_offset_effect() {
  return register_effect<ChannelGainOffset>(kInfo);
}

}  // namespace gc
