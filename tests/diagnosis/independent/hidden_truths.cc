#include "tests/diagnosis/independent/hidden_truths.h"

#include <cmath>
#include <functional>
#include <numbers>
#include <stdexcept>

#include "core/restoring_torque.h"
#include "tests/diagnosis/independent/base_models.h"
#include "tests/diagnosis/independent/recording_inputs.h"
#include "tests/diagnosis/independent/test_cell_noise.h"
#include "tests/diagnosis/independent/truth_physics.h"

namespace gc::independent {
namespace {

using Inputs = std::vector<MeasurementSample>;
using Truth = std::function<std::vector<SensorMoments>(const CouplingModel& base, const Inputs& inputs)>;
using SampleTruth = std::function<SensorMoments(const CouplingModel& base, const Inputs& inputs, std::size_t i)>;

struct Noise {
  std::string description;
  std::function<ChannelNoise(const Inputs& inputs, std::uint64_t seed)> make;
};

struct Recipe {
  std::string name;
  std::string physics;
  std::string base_without;  ///< the paper effect the base model lacks, "" for none
  LoadSequenceKind sequence;
  Truth truth;
  Noise noise;
  ExpectedNaming expected;
};

constexpr double kPi = std::numbers::pi;

Truth per_sample(SampleTruth f) {
  return [f](const CouplingModel& base, const Inputs& inputs) {
    std::vector<SensorMoments> truth(inputs.size());
    for (std::size_t i = 0; i < inputs.size(); ++i) truth[i] = f(base, inputs, i);
    return truth;
  };
}

// The base model itself: the noise-only cases.
Truth base_truth() {
  return per_sample([](const CouplingModel& base, const Inputs& in, std::size_t i) {
    return base.predict(in[i]).moments;
  });
}

// The base model at inputs changed by `change` (a misalignment the sensors do not see, a lag...).
/// The base model rebuilt around a changed coupling or contact options (not through an effect).
Truth rebuilt(std::function<void(CouplingDefinition&, ContactOptions&)> change) {
  return [change](const CouplingModel& base, const Inputs& in) {
    CouplingDefinition coupling = base.base_coupling();
    ContactOptions options = base.options();
    change(coupling, options);
    const CouplingModel truth(coupling, base.effects(), options);
    std::vector<SensorMoments> out;
    for (const MeasurementSample& s : in) out.push_back(truth.predict(s).moments);
    return out;
  };
}

Truth changed_inputs(std::function<MeasurementSample(const Inputs&, std::size_t)> change) {
  return per_sample([change](const CouplingModel& base, const Inputs& in, std::size_t i) {
    return base.predict(change(in, i)).moments;
  });
}

// The base model plus a moment added at the sensors.
Truth added_moment(std::function<SensorMoments(const CouplingModel&, const Inputs&, std::size_t)> extra) {
  return per_sample([extra](const CouplingModel& base, const Inputs& in, std::size_t i) {
    const SensorMoments m = base.predict(in[i]).moments;
    const SensorMoments e = extra(base, in, i);
    return SensorMoments{m.y_nm + e.y_nm, m.z_nm + e.z_nm};
  });
}

double jam_rad(const CouplingModel& base) { return base.geometry().jam_angle().angle_rad; }

std::vector<double> times(const Inputs& in) {
  std::vector<double> t;
  for (const MeasurementSample& s : in) t.push_back(s.time_s);
  return t;
}

// Noise recipes. The level is kNoiseSigmaNm throughout; the colour is what varies.
Noise white() {
  return {"white 2 kN·m", [](const Inputs& in, std::uint64_t seed) {
            return white_noise(in.size(), kNoiseSigmaNm, seed);
          }};
}
// phi 0.8 at 10 Hz: a correlation time of 0.45 s, a structural mode seen through the 1 Hz-ish
// bandwidth of the strain-gauge amplifiers.
Noise coloured() {
  return {"AR(1) phi 0.8, 2 kN·m", [](const Inputs& in, std::uint64_t seed) {
            return ar1_noise(in.size(), 0.8, kNoiseSigmaNm, seed);
          }};
}
Noise spiky() {
  return {"white 2 kN·m + 1 % outliers at 10 sigma", [](const Inputs& in, std::uint64_t seed) {
            return spiky_noise(in.size(), kNoiseSigmaNm, 0.01, 10.0, seed);
          }};
}
// A wandering bridge zero: 20 N·m steps reach about 0.9 kN·m over the 1920 samples.
Noise coloured_drifting() {
  return {"AR(1) phi 0.8, 2 kN·m + random-walk zero drift 20 N·m/sample",
          [](const Inputs& in, std::uint64_t seed) {
            return ar1_noise(in.size(), 0.8, kNoiseSigmaNm, seed) + random_walk_drift(in.size(), 20.0, seed + 7);
          }};
}
Noise white_drifting() {
  return {"white 2 kN·m + random-walk zero drift 20 N·m/sample", [](const Inputs& in, std::uint64_t seed) {
            return white_noise(in.size(), kNoiseSigmaNm, seed) + random_walk_drift(in.size(), 20.0, seed + 7);
          }};
}

// Friction coefficient the truth's contact is solved with: mu0 + a low-torque rise that decays
// exponentially (not as 1/T) + a quadratic (not linear) rise with misalignment.
double exponential_friction(double torque_nm, double zeta_rad, double jam) {
  const double r = zeta_rad / jam;
  return 0.08 + 0.03 * std::exp(-torque_nm / 4e5) + 0.06 * r * r;
}

std::vector<Recipe> recipes() {
  std::vector<Recipe> r;

  // Section 6.3's friction, in another functional form, for a base model without friction.
  r.push_back({"friction_other_form", "mu = 0.08 + 0.03 exp(-T / 0.4 MN·m) + 0.06 (zeta/xi)^2", "friction",
               LoadSequenceKind::moment_sweep,
               per_sample([](const CouplingModel& base, const Inputs& in, std::size_t i) {
                 const double jam = jam_rad(base);
                 return with_contact_change(base, in[i], [jam](OperatingPoint& p, double&) {
                   p.friction_coefficient = exponential_friction(p.torque_nm, p.misalignment_rad, jam);
                 });
               }),
               coloured(), {{"friction"}, {}, false, 1}});

  // Issue 8 class 1: the model has friction, with the wrong values (mu0 = 0.1 only); the truth's
  // rises at low torque and with misalignment.
  r.push_back({"friction_wrong_parameters", "mu = 0.07 + 0.025 * 1.5 MN·m / T + 0.08 zeta/xi (base: 0.1)", "",
               LoadSequenceKind::moment_sweep,
               per_sample([](const CouplingModel& base, const Inputs& in, std::size_t i) {
                 const double jam = jam_rad(base);
                 return with_contact_change(base, in[i], [jam](OperatingPoint& p, double&) {
                   p.friction_coefficient = 0.07 + 0.025 * 1.5e6 / p.torque_nm + 0.08 * p.misalignment_rad / jam;
                 });
               }),
               white(), {{"friction"}, {}, false, 1}});

  // A misalignment the sensors do not see: 19 % of the jam angle at 125 deg.
  r.push_back({"assembly_misalignment", "unseen misalignment vector 0.19 xi at 125 deg", "",
               LoadSequenceKind::moment_sweep,
               per_sample([](const CouplingModel& base, const Inputs& in, std::size_t i) {
                 return base.predict(with_added_misalignment(in[i], 0.19 * jam_rad(base), 125.0 * kPi / 180.0)).moments;
               }),
               coloured(), {{"assembly_misalignment"}, {}, false, 1}});

  // Eq 48's weight, by its own statics, 25 % heavier than the definition (instrumentation on the
  // hub); at one tilt it is a channel offset, so either name is right.
  r.push_back({"self_weight_heavier", "-1.25 (W_c + w_sh L_s / 2) L_s cos(gamma) on M_sy'", "self_weight",
               LoadSequenceKind::moment_sweep,
               added_moment([](const CouplingModel& base, const Inputs&, std::size_t) {
                 return SensorMoments{-1.25 * weight_moment_nm(base.base_coupling()), 0.0};
               }),
               coloured_drifting(), {{"self_weight", "channel_gain_offset"}, {}, false, 1}});

  r.push_back({"channel_gain_offset", "M_sy' x 1.04 + 6 kN·m, M_sz' x 0.97 - 4 kN·m", "",
               LoadSequenceKind::moment_sweep,
               per_sample([](const CouplingModel& base, const Inputs& in, std::size_t i) {
                 const SensorMoments m = base.predict(in[i]).moments;
                 return SensorMoments{1.04 * m.y_nm + 6000.0, 0.97 * m.z_nm - 4000.0};
               }),
               white_drifting(), {{"channel_gain_offset"}, {}, false, 1}});

  // The rig's compliance: the coupling sees 15 % more misalignment than is measured.
  r.push_back({"misalignment_scale", "true zeta = 1.15 measured zeta", "",
               LoadSequenceKind::moment_sweep,
               changed_inputs([](const Inputs& in, std::size_t i) {
                 MeasurementSample s = in[i];
                 s.misalignment_rad *= 1.15;
                 return s;
               }),
               coloured(), {{"compliance", "misalignment_scale"}, {"misalignment scale", "scale of the misalignment", "scale error"}, false, 1}});

  // Rim flexibility in series with the teeth, C_rim = 2.5 C: the mesh at C_rim / (C + C_rim) of
  // eq 5's stiffness, through the coupling's Young's modulus, the model rebuilt around it.
  r.push_back({"rim_compliance", "mesh stiffness C C_rim / (C + C_rim), C_rim = 2.5 C (0.714 C)", "",
               LoadSequenceKind::moment_sweep,
               rebuilt([](CouplingDefinition& coupling, ContactOptions&) {
                 coupling.youngs_modulus_pa *= 2.5 / (1.0 + 2.5);
               }),
               coloured(), {{"compliance"}, {}, false, 1}});

  // A sleeve out of round by 30 um: every tooth pair separated by that much more (eq 11's z_o),
  // set on the contact options of a rebuilt model.
  r.push_back({"sleeve_out_of_round", "tooth separation z_o + 30 um", "",
               LoadSequenceKind::moment_sweep,
               rebuilt([](CouplingDefinition&, ContactOptions& options) { options.spacing_error_m += 3e-5; }),
               white(), {{"spacing_errors"}, {}, false, 1}});

  // The load-application device lags the measurement by more at higher torque.
  r.push_back({"hysteresis_torque_lag", "zeta lags by (0.5 + 0.4 T / 1.5 MN·m) mrad against the direction of travel", "",
               LoadSequenceKind::moment_sweep,
               [](const CouplingModel& base, const Inputs& in) {
                 const std::vector<int> travel = travel_direction(in);
                 std::vector<SensorMoments> truth(in.size());
                 for (std::size_t i = 0; i < in.size(); ++i) {
                   MeasurementSample s = in[i];
                   const double lag = 0.0005 + 0.0004 * s.torque_nm / 1.5e6;
                   s.misalignment_rad = std::max(0.0, s.misalignment_rad - lag * travel[i]);
                   truth[i] = base.predict(s).moments;
                 }
                 return truth;
               },
               white(), {{"hysteresis"}, {}, false, 1}});

  // The hub sags on the sleeve below the restoring torque, fading smoothly (logistic) as the
  // torque lifts it, rather than linearly to a threshold.
  r.push_back({"eccentricity_smooth", "2 mrad at 107 deg, faded by 1 / (1 + exp((T - 0.85 T_m) / 0.08 T_m))", "",
               LoadSequenceKind::torque_sweep,
               per_sample([](const CouplingModel& base, const Inputs& in, std::size_t i) {
                 const double tm = restoring_torque(base.geometry()).torque_nm;
                 const double fade = 1.0 / (1.0 + std::exp((in[i].torque_nm - 0.85 * tm) / (0.08 * tm)));
                 return base.predict(with_added_misalignment(in[i], 0.002 * fade, 107.0 * kPi / 180.0)).moments;
               }),
               coloured(), {{"eccentricity"}, {}, false, 1}});

  // The moment direction turns with the pressure angle by a share that grows with torque.
  r.push_back({"pressure_angle_with_torque", "moments turn by 1.2 phi T / (T + 0.3 MN·m)", "pressure_angle_rotation",
               LoadSequenceKind::moment_sweep,
               per_sample([](const CouplingModel& base, const Inputs& in, std::size_t i) {
                 const double phi = base.geometry().pressure_angle_rad();
                 return with_contact_change(base, in[i], [phi](OperatingPoint& p, double& shift) {
                   shift += 1.2 * phi * p.torque_nm / (p.torque_nm + 3e5);
                 });
               }),
               coloured_drifting(), {{"pressure_angle_rotation"}, {}, false, 1}});

  // Outside the library, smooth: a moment along the model's own moment direction growing with
  // T zeta (0.8 N·m per N·m rad: about 10 kN·m at 1.5 MN·m and 0.6 xi).
  r.push_back({"outside_torque_times_misalignment", "+0.8 T zeta along the model's moment direction", "",
               LoadSequenceKind::moment_sweep,
               added_moment([](const CouplingModel& base, const Inputs& in, std::size_t i) {
                 const Eigen::Vector2d u = contact_moment_direction(base, in[i]);
                 const double size = 0.8 * in[i].torque_nm * in[i].misalignment_rad;
                 return SensorMoments{size * u.x(), size * u.y()};
               }),
               coloured(),
               {{}, {"t*zeta", "t * zeta", "torque x misalignment", "torque * misalignment", "torque·misalignment",
                     "torque times misalignment",
                     "along the moment"}, false, 1}});

  // Outside the library, by sign: a constant 8 kN·m along the misalignment direction whose sign
  // follows the direction of travel of the amplitude (a stick-slip moment of the slide).
  r.push_back({"outside_travel_sign", "8 kN·m x sign(d zeta / dt) along beta", "",
               LoadSequenceKind::moment_sweep,
               [](const CouplingModel& base, const Inputs& in) {
                 const std::vector<int> travel = travel_direction(in);
                 std::vector<SensorMoments> truth(in.size());
                 for (std::size_t i = 0; i < in.size(); ++i) {
                   const SensorMoments m = base.predict(in[i]).moments;
                   const double size = 8000.0 * travel[i];
                   truth[i] = {m.y_nm + size * std::cos(in[i].direction_rad), m.z_nm + size * std::sin(in[i].direction_rad)};
                 }
                 return truth;
               },
               white(), {{}, {"direction of travel", "loading direction", "loading_direction"}, false, 1}});

  r.push_back({"noise_white", "nothing: the base is the truth", "", LoadSequenceKind::moment_sweep, base_truth(),
               white(), {{}, {}, true, 1}});
  r.push_back({"noise_ar1", "nothing: the base is the truth", "", LoadSequenceKind::moment_sweep, base_truth(),
               coloured(), {{}, {}, true, 1}});
  r.push_back({"noise_spiky", "nothing: the base is the truth", "", LoadSequenceKind::moment_sweep, base_truth(),
               spiky(), {{}, {}, true, 1}});

  // The zero of M_sz' drifts with the cell's temperature: 6 kN·m over the run plus a 3 kN·m
  // swing on a 70 s period. Part of the truth (the same in both recordings).
  r.push_back({"zero_drift", "M_sz' zero: +6 kN·m t / t_end + 3 kN·m sin(2 pi t / 70 s + phase)", "",
               LoadSequenceKind::moment_sweep,
               [](const CouplingModel& base, const Inputs& in) {
                 const ChannelNoise drift = sine_drift(times(in), 3000.0, 70.0, 99, false, true);
                 std::vector<SensorMoments> truth(in.size());
                 for (std::size_t i = 0; i < in.size(); ++i) {
                   const SensorMoments m = base.predict(in[i]).moments;
                   truth[i] = {m.y_nm, m.z_nm + 6000.0 * in[i].time_s / in.back().time_s + drift[i].z_nm};
                 }
                 return truth;
               },
               coloured(), {{}, {"drift"}, false, 1}});

  // Windage or bearing drag: 3 kN·m per rpm on M_sz' about the mean speed of 12 rpm.
  r.push_back({"speed_drag", "+3 kN·m/rpm (speed - 12 rpm) on M_sz'", "", LoadSequenceKind::moment_sweep,
               added_moment([](const CouplingModel&, const Inputs& in, std::size_t i) {
                 return SensorMoments{0.0, 3000.0 * (*in[i].speed_rpm - 12.0)};
               }),
               spiky(), {{}, {"speed"}, false, 1}});

  // Unbalance or runout: a moment fixed to the rotating shaft, seen once per revolution.
  r.push_back({"revolution_ripple", "5 kN·m (sin, cos)(phase + 0.7) on (M_sy', M_sz')", "",
               LoadSequenceKind::moment_sweep,
               added_moment([](const CouplingModel&, const Inputs& in, std::size_t i) {
                 const double a = *in[i].rotation_phase_rad + 0.7;
                 return SensorMoments{5000.0 * std::sin(a), 5000.0 * std::cos(a)};
               }),
               coloured(), {{}, {"revolution", "rotation phase", "once per", "phase"}, false, 1}});

  // The bridges are not perfectly orthogonal: 5 % of M_sz' reads on M_sy'.
  r.push_back({"cross_talk", "M_sy' reads M_sy' + 0.05 M_sz'", "", LoadSequenceKind::moment_sweep,
               per_sample([](const CouplingModel& base, const Inputs& in, std::size_t i) {
                 const SensorMoments m = base.predict(in[i]).moments;
                 return SensorMoments{m.y_nm + 0.05 * m.z_nm, m.z_nm};
               }),
               white(), {{}, {"cross-talk", "crosstalk", "cross talk"}, false, 1}});

  // Oil thinning as the cell warms: friction falls 0.0015 per K from 0.1 at 45 deg C.
  r.push_back({"temperature_friction", "mu = 0.1 - 0.0015 /K (temperature - 45 deg C)", "",
               LoadSequenceKind::moment_sweep,
               per_sample([](const CouplingModel& base, const Inputs& in, std::size_t i) {
                 const double mu = 0.1 - 0.0015 * (*in[i].temperature_c - 45.0);
                 return with_contact_change(base, in[i], [mu](OperatingPoint& p, double&) { p.friction_coefficient = mu; });
               }),
               coloured_drifting(), {{"friction"}, {"temperature"}, false, 1}});

  // Two at once: an unseen misalignment and an offset on M_sy'.
  r.push_back({"misalignment_and_offset", "unseen 0.12 xi at -60 deg, and +5 kN·m on M_sy'", "",
               LoadSequenceKind::moment_sweep,
               per_sample([](const CouplingModel& base, const Inputs& in, std::size_t i) {
                 const SensorMoments m =
                     base.predict(with_added_misalignment(in[i], 0.12 * jam_rad(base), -60.0 * kPi / 180.0)).moments;
                 return SensorMoments{m.y_nm + 5000.0, m.z_nm};
               }),
               coloured(), {{"assembly_misalignment", "channel_gain_offset"}, {}, false, 2}});
  return r;
}

std::vector<RecordedSample> record(const Inputs& inputs, const std::vector<SensorMoments>& truth,
                                   const ChannelNoise& noise) {
  std::vector<RecordedSample> recording(inputs.size());
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    recording[i].input = inputs[i];
    recording[i].measured = {truth[i].y_nm + noise[i].y_nm, truth[i].z_nm + noise[i].z_nm};
  }
  return recording;
}

// FNV-1a of the name: a seed that is the same on every platform (std::hash is not).
std::uint64_t name_seed(const std::string& name) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (unsigned char c : name) h = (h ^ c) * 0x100000001b3ULL;
  return h;
}

}  // namespace

std::vector<std::string> hidden_truth_names() {
  std::vector<std::string> names;
  for (const Recipe& r : recipes()) names.push_back(r.name);
  return names;
}

HiddenTruthCase hidden_truth_case(const std::string& name) {
  for (const Recipe& r : recipes()) {
    if (r.name != name) continue;
    CouplingModel base = paper_model(r.base_without);
    Inputs inputs = recording_inputs(r.sequence);
    std::vector<SensorMoments> truth = r.truth(base, inputs);
    // Seeds from the name: each case its own noise, the held-out recording another draw.
    const std::uint64_t seed = name_seed(name);
    std::vector<RecordedSample> training = record(inputs, truth, r.noise.make(inputs, seed));
    std::vector<RecordedSample> held_out = record(inputs, truth, r.noise.make(inputs, seed * 31 + 1000003));
    return {r.name, r.physics, r.noise.description, std::move(base), std::move(inputs), std::move(truth),
            std::move(training), std::move(held_out), r.expected};
  }
  throw std::invalid_argument("no hidden-truth case named " + name);
}

}  // namespace gc::independent
