// The continuous form of eqs 42-43's quarter sums and eq 13's residue (docs/model.md): the
// paper's int(qN/4) makes |M| a sawtooth in torque and misalignment with steps of 6-8 %, which a
// real coupling need not have. As an effect, the form is a model part the diagnosis can try like
// any other, so that measurements that prefer the continuous form say so instead of bending some
// other effect's parameters to follow the saw.
//
// One parameter, s, the share of the paper's sawtooth the coupling smooths away:
//   M = M_paper + s (M_continuous - M_paper)        (both by eqs 42-47, at the same state)
// s = 1 (the default) is the continuous form, exactly the contact option; s = 0 the paper's form.
// Between, a sawtooth partly smoothed, as by teeth that enter contact over a spread of spacing
// errors. Outside [0, 1] the recording's steps at the quarter-sum crossings are deeper than the
// paper's (s < 0) or turned over (s > 1): the crossings are the model's, the depth is not.
#include <Eigen/Dense>

#include "core/coupling_frame.h"
#include "core/effects/registration.h"
#include "core/induced_moments.h"

namespace gc {
namespace {

const EffectInfo kInfo{
    "continuous_quarter_sums",
    "The induced moments without the sawtooth of the paper's quarter sums (eqs 13, 42-43 in their "
    "continuous form): the coupling's moment grows smoothly as teeth enter contact.",
    "Section 4.3 (eqs 42-43), docs/model.md",
    {{"smoothed_share", "-",
      "s, the share of the paper's int(qN/4) sawtooth smoothed away: 1 the continuous form, 0 the paper's",
      -20.0, 20.0, 0.0, 1.0, {0.0, 1.0}, false, 0.0,
      "the tooth count and the load sharing q (eqs 20-22), or a ripple of the bending channels at those "
      "torques: the recording's steps at the quarter-sum crossings are deeper than the paper's or turned over"}}};

class ContinuousQuarterSums final : public Effect {
 public:
  explicit ContinuousQuarterSums(const ParameterValues& values)
      : Effect(kInfo, values), share_(value("smoothed_share")) {}

  void adjust_inputs(const MeasurementSample&, const ModelContext&, ModelState& state) const override {
    if (share_ == 1.0) state.contact.continuous_quarter_sums = true;  // the option itself, bit for bit
  }

  void adjust_outputs(const MeasurementSample&, const ModelContext& context, const ModelState& state,
                      SensorMoments& moments) const override {
    if (share_ == 1.0) return;
    ContactOptions paper = state.contact, continuous = state.contact;
    paper.continuous_quarter_sums = false;
    continuous.continuous_quarter_sums = true;
    const QuarterSums a = double_prime_moments(context.geometry, state.point, paper);
    const QuarterSums b = double_prime_moments(context.geometry, state.point, continuous);
    // Eqs 44-47 as the model turned its own moments; the model's form counts as s = 1 or 0.
    const Eigen::Vector2d change = double_prime_to_coupling(state.frame_shift_rad, state.point.direction_rad) *
                                   Eigen::Vector2d(b.moment_y_dd_nm - a.moment_y_dd_nm, b.moment_z_dd_nm - a.moment_z_dd_nm);
    const double weight = share_ - (state.contact.continuous_quarter_sums ? 1.0 : 0.0);
    moments.y_nm += weight * change.x();
    moments.z_nm += weight * change.y();
  }

 private:
  double share_;  // s [-]
};

}  // namespace

EffectRegistration continuous_quarter_sums_effect() { return register_effect<ContinuousQuarterSums>(kInfo); }

}  // namespace gc
