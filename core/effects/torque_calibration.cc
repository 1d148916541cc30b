// A calibration error of the torque transducer: the recorded torque is not the torque the
// coupling carries (Section 3: the torque is measured by the dynamometer's transducer, and every
// contact quantity of eqs 1-43 scales with it). A strain-gauge torque flange is linear to its
// calibration slope only; a bridge loaded near its range bends over, so the error grows with
// the torque. The coupling carries
//   T_true = T_recorded (1 + k + c T_recorded / (1 MN·m)),
// a slope error k and a curvature c per MN·m of recorded torque.
#include "core/effects/registration.h"

namespace gc {
namespace {

constexpr double kCurvatureTorqueNm = 1.0e6;  // the torque c is given per [N·m]

const EffectInfo kInfo{
    "torque_calibration",
    "A calibration error of the torque transducer: the coupling carries T (1 + k + c T / 1 MN·m) "
    "when T is recorded, a slope error k and a curvature c.",
    "Section 3 (instrumentation: torque from the dynamometer's transducer)",
    {{"slope_error", "-", "k, the torque carried over the recorded, less 1, at low torque", -0.5, 0.5, 0.0, 0.0,
      {-0.05, 0.05}, false, 0.0, "the torque transducer's calibration (shunt calibration, zero)"},
     {"curvature_per_mnm", "-", "c, how the ratio changes per MN·m of recorded torque", -0.5, 0.5, 0.0, 0.0,
      {-0.05, 0.05}, false, 0.0, "the torque transducer's linearity near its range"}}};

class TorqueCalibration final : public Effect {
 public:
  explicit TorqueCalibration(const ParameterValues& values)
      : Effect(kInfo, values), k_(value("slope_error")), c_(value("curvature_per_mnm")) {}

  void adjust_inputs(const MeasurementSample&, const ModelContext&, ModelState& state) const override {
    const double t = state.point.torque_nm;
    state.point.torque_nm = t * (1.0 + k_ + c_ * t / kCurvatureTorqueNm);
  }

 private:
  double k_, c_;
};

}  // namespace

EffectRegistration torque_calibration_effect() { return register_effect<TorqueCalibration>(kInfo); }

}  // namespace gc
