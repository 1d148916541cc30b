#include "tests/diagnosis/campaign/cases.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <thread>

#include "tests/diagnosis/independent/base_models.h"

namespace gc::campaign {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kDeg = kPi / 180.0;

const CouplingModel& paper() {
  static const CouplingModel model = independent::paper_model();
  return model;
}

MeasurementSample sample_of(const InputRow& r) {
  MeasurementSample s;
  s.time_s = r.time_s;
  s.torque_nm = r.torque_nm;
  s.misalignment_rad = r.zeta_rad;
  s.direction_rad = r.beta_rad;
  s.speed_rpm = r.speed_rpm;
  s.temperature_c = r.temperature_c;
  s.rotation_phase_rad = r.phase_rad;
  return s;
}

// A misalignment vector added to the commanded one in the coupling's frame:
// (zeta cos beta, zeta sin beta) + (a cos g, a sin g), back to amplitude and direction.
void add_misalignment_vector(InputRow& r, double amplitude_rad, double direction_rad) {
  const double y = r.zeta_rad * std::cos(r.beta_rad) + amplitude_rad * std::cos(direction_rad);
  const double z = r.zeta_rad * std::sin(r.beta_rad) + amplitude_rad * std::sin(direction_rad);
  r.zeta_rad = std::hypot(y, z);
  r.beta_rad = std::atan2(z, y);
}

// The truth when nothing is hidden: the DAQ logs the true inputs, the moments are the paper's.
void plain(const std::vector<InputRow>& in, Run, Recording& out) {
  out.logged = in;
  out.truth = base_moments(in);
}

// A once- or k-times-per-revolution moment vector rotating with the shaft, seen by the stationary
// bridges as y = A cos(k phi + p), z = A sin(k phi + p).
void add_shaft_order(Recording& out, const std::vector<InputRow>& in, int order, double phase,
                     const std::function<double(const InputRow&)>& amplitude_nm) {
  for (std::size_t i = 0; i < in.size(); ++i) {
    const double a = amplitude_nm(in[i]);
    out.truth[i].y_nm += a * std::cos(order * in[i].phase_rad + phase);
    out.truth[i].z_nm += a * std::sin(order * in[i].phase_rad + phase);
  }
}

NoiseSpec noise_student_t() {
  NoiseSpec s;
  s.t3_scale_nm = 1200.0;  // std 2.08 kN·m, heavy tails
  return s;
}

NoiseSpec noise_ar_wandering() {
  NoiseSpec s;
  s.ar_sigma_nm = 2000.0;
  s.ar_tau_s = 1.5;
  s.ar_level_wanders = true;
  s.t3_scale_nm = 300.0;
  return s;
}

NoiseSpec noise_quantised() {
  NoiseSpec s;
  s.t3_scale_nm = 700.0;
  s.ar_sigma_nm = 1200.0;
  s.ar_tau_s = 1.0;
  s.lsb_nm = 400.0;
  s.duplicate_share = 0.02;
  s.empty_cells = 6;
  return s;
}

}  // namespace

SensorMoments base_moment(const InputRow& r) { return paper().predict(sample_of(r)).moments; }

std::vector<SensorMoments> base_moments(const std::vector<InputRow>& inputs) {
  std::vector<SensorMoments> out(inputs.size());
  const unsigned workers = std::max(1u, std::min(4u, std::thread::hardware_concurrency()));
  std::vector<std::thread> pool;
  for (unsigned w = 0; w < workers; ++w) {
    pool.emplace_back([&, w] {
      for (std::size_t i = w; i < inputs.size(); i += workers) out[i] = base_moment(inputs[i]);
    });
  }
  for (auto& t : pool) t.join();
  return out;
}

double jam_angle_rad() { return 0.7509 * kDeg; }  // checked against `gearcoupling jam-angle` in the test

std::vector<Case> campaign_cases() {
  std::vector<Case> cases;
  const NoiseSpec daq = standard_daq();

  // ---------------------------------------------------------------- noise only: claim nothing
  {
    Case c;
    c.name = "noise_student_t3";
    c.truth_text = "no effect; white Student-t(3) noise, scale 1.2 kN·m (std 2.1 kN·m)";
    c.noise = noise_student_t();
    c.seed = 101;
    c.effect = plain;
    cases.push_back(c);
  }
  {
    Case c;
    c.name = "noise_ar1_wandering_level";
    c.truth_text = "no effect; AR(1) noise tau 1.5 s, sigma 2 kN·m x a slow factor 0.5-2, small t(3) floor";
    c.noise = noise_ar_wandering();
    c.seed = 102;
    c.effect = plain;
    cases.push_back(c);
  }
  {
    Case c;
    c.name = "noise_quantised_duplicates";
    c.truth_text = "no effect; 400 N·m ADC steps, 2 % duplicated time stamps, 6 empty cells, coarse export";
    c.noise = noise_quantised();
    c.coarse_export = true;
    c.seed = 103;
    c.effect = plain;
    cases.push_back(c);
  }

  // ---------------------------------------------------------------- shaft orders and clock effects
  {
    // An oval (out-of-round) sleeve: the tooth load distribution pulses twice per revolution;
    // the bending moment it adds rotates with the shaft at twice its angle. Amplitude grows with
    // the tooth loads: 1 kN·m + 3 kN·m x T / 2.5 MN·m.
    Case c;
    c.name = "ripple_twice_per_rev_oval_sleeve";
    c.truth_text = "2x shaft order: y = A cos(2 phi + 0.4), z = A sin(2 phi + 0.4), A = 1 kN·m + 3 kN·m T/2.5 MN·m";
    c.must_name = {{"second shaft order", {R"(order_2_)", R"(spacing_errors)"}}};
    c.noise = daq;
    c.seed = 201;
    c.effect = [](const std::vector<InputRow>& in, Run r, Recording& out) {
      plain(in, r, out);
      add_shaft_order(out, in, 2, 0.4, [](const InputRow& x) { return 1000.0 + 3000.0 * x.torque_nm / 2.5e6; });
    };
    cases.push_back(c);
  }
  {
    // Unbalance / bow of the floating shaft: a centrifugal force rotating once per revolution,
    // growing with the square of speed: A = 4 kN·m x (n / 15 rpm)^2; visible mainly in the
    // 3-15-3 rpm speed run and at 12 rpm.
    Case c;
    c.name = "ripple_once_per_rev_unbalance";
    c.truth_text = "1x shaft order: y = A cos(phi + 1.1), z = A sin(phi + 1.1), A = 4 kN·m (n/15 rpm)^2";
    c.must_name = {{"once per revolution", {R"(revolution_)"}}};
    c.noise = daq;
    c.seed = 202;
    c.effect = [](const std::vector<InputRow>& in, Run r, Recording& out) {
      plain(in, r, out);
      add_shaft_order(out, in, 1, 1.1, [](const InputRow& x) { return 4000.0 * std::pow(x.speed_rpm / 15.0, 2); });
    };
    cases.push_back(c);
  }
  {
    // Electrical pickup from the lubrication pump's motor drive at 0.4 Hz (period 2.5 s): a sine
    // on both bridges, locked to the DAQ clock, explained by no input.
    Case c;
    c.name = "pump_interference_0p4hz";
    c.truth_text = "y += 3 kN·m sin(2 pi 0.4 t + 0.7), z += 2 kN·m sin(2 pi 0.4 t + 2.0), t the DAQ clock";
    c.must_name = {{"2.5 s cycle", {R"(time_cycle_2\.[45][0-9]*s_)"}}};
    c.noise = daq;
    c.seed = 203;
    c.effect = [](const std::vector<InputRow>& in, Run r, Recording& out) {
      plain(in, r, out);
      for (std::size_t i = 0; i < in.size(); ++i) {
        const double w = 2 * kPi * 0.4 * in[i].time_s;
        out.truth[i].y_nm += 3000.0 * std::sin(w + 0.7);
        out.truth[i].z_nm += 2000.0 * std::sin(w + 2.0);
      }
    };
    cases.push_back(c);
  }
  {
    // The M_sy' bridge re-zeroed by an operator at t = 687.3 s (DAQ clock): +9 kN·m (about 4
    // noise sigmas) from then on. The held-out run comes later on the same clock: the offset
    // persists (no second re-zero).
    Case c;
    c.name = "bridge_rezero_step_y";
    c.truth_text = "y += 9 kN·m for t >= 687.3 s (persists into the held-out run)";
    c.must_name = {{"step near 687 s on y", {R"(step_at_(68[2-9]|69[0-2])(\.[0-9]+)?s_on_y)"}}};
    c.noise = daq;
    c.seed = 204;
    c.effect = [](const std::vector<InputRow>& in, Run r, Recording& out) {
      plain(in, r, out);
      for (std::size_t i = 0; i < in.size(); ++i) {
        if (in[i].time_s >= 687.3) out.truth[i].y_nm += 9000.0;
      }
    };
    cases.push_back(c);
  }
  {
    // DAQ skew: the bending channels pass an extra filter/buffer and arrive 0.3 s (3 samples)
    // after the inputs logged in the same row: row i carries the moments of row i - 3's inputs.
    Case c;
    c.name = "daq_skew_0p3s";
    c.truth_text = "moments of the inputs 0.3 s earlier (3 samples)";
    c.must_name = {{"delay / lag", {R"(delay)", R"(\blag)"}, true}};
    c.noise = daq;
    c.seed = 205;
    c.effect = [](const std::vector<InputRow>& in, Run, Recording& out) {
      out.logged = in;
      const std::vector<SensorMoments> m = base_moments(in);
      out.truth.resize(in.size());
      for (std::size_t i = 0; i < in.size(); ++i) out.truth[i] = m[i >= 3 ? i - 3 : 0];
    };
    cases.push_back(c);
  }
  {
    // Demodulation of rotating gauges: the conditioner averages the moments over one shaft
    // revolution (a trailing window of 60 / n seconds, 5 s at 12 rpm, 20 s at 3 rpm).
    Case c;
    c.name = "demodulation_lag_one_rev";
    c.truth_text = "moments averaged over the last revolution (window 60/n s, trailing)";
    c.must_name = {{"delay / lag", {R"(delay)", R"(\blag)"}, true}};
    c.noise = daq;
    c.seed = 206;
    c.effect = [](const std::vector<InputRow>& in, Run, Recording& out) {
      out.logged = in;
      const std::vector<SensorMoments> m = base_moments(in);
      std::vector<double> cy(in.size() + 1, 0.0), cz(in.size() + 1, 0.0);
      for (std::size_t i = 0; i < in.size(); ++i) cy[i + 1] = cy[i] + m[i].y_nm, cz[i + 1] = cz[i] + m[i].z_nm;
      out.truth.resize(in.size());
      for (std::size_t i = 0; i < in.size(); ++i) {
        const auto window = static_cast<std::size_t>(std::lround(60.0 / in[i].speed_rpm * kSampleRateHz));
        const std::size_t lo = i + 1 >= window ? i + 1 - window : 0;
        const double n = static_cast<double>(i + 1 - lo);
        out.truth[i] = {(cy[i + 1] - cy[lo]) / n, (cz[i + 1] - cz[lo]) / n};
      }
    };
    cases.push_back(c);
  }

  // ---------------------------------------------------------------- rig and sensor physics
  {
    // The rig's assembly leaves a fixed misalignment vector of 0.06 deg at 3.10 rad (nearly
    // opposite the beta = 0 sweeps), added to the commanded one; the DAQ logs the command.
    Case c;
    c.name = "assembly_offset_near_pi";
    c.truth_text = "true misalignment = commanded + 0.06 deg at 3.10 rad (vector sum)";
    c.must_name = {{"assembly misalignment", {R"(^assembly_misalignment$)", R"(misalignment)"}}};
    c.noise = daq;
    c.seed = 301;
    c.effect = [](const std::vector<InputRow>& in, Run, Recording& out) {
      out.logged = in;
      std::vector<InputRow> t = in;
      for (InputRow& r : t) add_misalignment_vector(r, 0.06 * kDeg, 3.10);
      out.truth = base_moments(t);
    };
    cases.push_back(c);
  }
  {
    // A poorly aligned rig: an offset of 38 % of the jam angle at 1.0 rad. The sweeps stop at
    // 0.30 deg so that the true misalignment stays below 80 % of the jam angle.
    Case c;
    c.name = "assembly_offset_38pct_jam";
    c.truth_text = "true misalignment = commanded + 0.38 x jam angle (0.285 deg) at 1.0 rad; sweeps to 0.30 deg";
    c.must_name = {{"assembly misalignment", {R"(^assembly_misalignment$)", R"(misalignment)"}}};
    c.noise = daq;
    c.zeta_max_deg = 0.30;
    c.seed = 302;
    c.effect = [](const std::vector<InputRow>& in, Run, Recording& out) {
      out.logged = in;
      std::vector<InputRow> t = in;
      for (InputRow& r : t) add_misalignment_vector(r, 0.38 * jam_angle_rad(), 1.0);
      out.truth = base_moments(t);
    };
    cases.push_back(c);
  }
  {
    // The torque transducer's calibration is nonlinear: it logs T + 0.04 T^2 / 2.5 MN·m (4 % high
    // at full scale, 0.3 % at 0.2 MN·m). The coupling sees the true torque.
    Case c;
    c.name = "torque_sensor_quadratic";
    c.truth_text = "logged torque = T (1 + 0.04 T / 2.5 MN·m); physics at the true T";
    c.must_name = {{"torque (sensor)", {R"(torque)"}}};
    c.noise = daq;
    c.seed = 303;
    c.effect = [](const std::vector<InputRow>& in, Run, Recording& out) {
      out.truth = base_moments(in);
      out.logged = in;
      for (InputRow& r : out.logged) r.torque_nm = r.torque_nm * (1.0 + 0.04 * r.torque_nm / 2.5e6);
    };
    cases.push_back(c);
  }
  {
    // Two effects of the rig's structure: (a) a heavier floating assembly than the model's: a
    // 3.6 kN brake disc at the coupling end adds 3.6 kN x 2.8 m = 10.08 kN·m to the gravity
    // moment, which the model books on M_sy' with a negative sign (eq 48); (b) thermal growth of
    // the gearbox housing: the misalignment gains 0.0035 deg per deg C of oil temperature above
    // 35 deg C, along beta = pi/2 (the housing rises).
    Case c;
    c.name = "heavier_weight_thermal_misalignment";
    c.truth_text = "M_sy' -= 10.08 kN·m; misalignment += 0.0035 deg/degC x (theta - 35) at pi/2 (vector)";
    c.must_name = {{"self weight", {R"(self_weight)", R"(weight)"}},
                   {"temperature-driven misalignment", {R"(temperature)"}}};
    c.noise = daq;
    c.seed = 304;
    c.effect = [](const std::vector<InputRow>& in, Run, Recording& out) {
      out.logged = in;
      std::vector<InputRow> t = in;
      for (InputRow& r : t) add_misalignment_vector(r, 0.0035 * kDeg * (r.temperature_c - 35.0), kPi / 2);
      out.truth = base_moments(t);
      for (SensorMoments& m : out.truth) m.y_nm -= 3600.0 * 2.8;
    };
    cases.push_back(c);
  }
  {
    // Rig hysteresis: Coulomb friction in the misalignment actuator's pivots adds a moment along
    // the misalignment direction whose sign follows the direction of travel and sticks when the
    // travel stops: dM = H s (cos beta, sin beta), H = 3 kN·m + 3 kN·m x T / 2.5 MN·m,
    // s = sign(dzeta/dt) when |dzeta/dt| > 2e-5 rad/s, else the last sign (0 before any travel).
    Case c;
    c.name = "rig_hysteresis_travel";
    c.truth_text = "dM = H s (cos b, sin b), H = 3 + 3 T/2.5MN·m kN·m, s = sticky sign of dzeta/dt";
    c.must_name = {{"direction of travel", {R"(^hysteresis$)", R"(travel_sign)"}}};
    // The DAQ's channels are calibrated here: a gain and offset of both would be a wrong answer.
    c.must_not_claim = {R"(^channel_gain_offset$)"};
    c.noise = daq;
    c.seed = 305;
    c.effect = [](const std::vector<InputRow>& in, Run r, Recording& out) {
      plain(in, r, out);
      double s = 0.0;
      for (std::size_t i = 1; i < in.size(); ++i) {
        const double rate = (in[i].zeta_rad - in[i - 1].zeta_rad) / kDt;
        if (std::abs(rate) > 2e-5) s = rate > 0 ? 1.0 : -1.0;
        const double h = 3000.0 + 3000.0 * in[i].torque_nm / 2.5e6;
        out.truth[i].y_nm += h * s * std::cos(in[i].beta_rad);
        out.truth[i].z_nm += h * s * std::sin(in[i].beta_rad);
      }
    };
    cases.push_back(c);
  }

  // ---------------------------------------------------------------- two at once
  {
    Case c;
    c.name = "skew_0p4s_plus_step_z";
    c.truth_text = "moments 0.4 s late (4 samples) and z -= 8 kN·m for t >= 902.4 s";
    c.must_name = {{"delay / lag", {R"(delay)", R"(\blag)"}, true},
                   {"step near 902 s on z", {R"(step_at_(89[7-9]|90[0-7])(\.[0-9]+)?s_on_z)"}}};
    c.noise = daq;
    c.seed = 401;
    c.effect = [](const std::vector<InputRow>& in, Run, Recording& out) {
      out.logged = in;
      const std::vector<SensorMoments> m = base_moments(in);
      out.truth.resize(in.size());
      for (std::size_t i = 0; i < in.size(); ++i) {
        out.truth[i] = m[i >= 4 ? i - 4 : 0];
        if (in[i].time_s >= 902.4) out.truth[i].z_nm -= 8000.0;
      }
    };
    cases.push_back(c);
  }
  {
    Case c;
    c.name = "offset_near_pi_plus_twice_rev";
    c.truth_text = "commanded + 0.06 deg at 3.10 rad, and a constant 3 kN·m 2x order (phase 2.2)";
    c.must_name = {{"assembly misalignment", {R"(^assembly_misalignment$)", R"(misalignment)"}},
                   {"second shaft order", {R"(order_2_)", R"(spacing_errors)"}}};
    c.noise = daq;
    c.seed = 402;
    c.effect = [](const std::vector<InputRow>& in, Run, Recording& out) {
      out.logged = in;
      std::vector<InputRow> t = in;
      for (InputRow& r : t) add_misalignment_vector(r, 0.06 * kDeg, 3.10);
      out.truth = base_moments(t);
      add_shaft_order(out, in, 2, 2.2, [](const InputRow&) { return 3000.0; });
    };
    cases.push_back(c);
  }

  // ---------------------------------------------------------------- low SNR, long recording
  {
    // 0.3 sigma of the standard DAQ noise (about 2.2 kN·m): 650 N·m, constant, 2x order. On
    // 13,740 rows its amplitude would be about 3 standard errors; on 100,000 rows about 8.
    Case c;
    c.name = "low_snr_twice_rev_100k";
    c.truth_text = "2x shaft order, constant 650 N·m (0.3 sigma), phase -0.9; 100,000 rows";
    c.must_name = {{"second shaft order", {R"(order_2_)", R"(spacing_errors)"}}};
    c.noise = daq;
    c.training_rows = 100000;
    c.held_out_rows = 100000;
    c.seed = 501;
    c.effect = [](const std::vector<InputRow>& in, Run r, Recording& out) {
      plain(in, r, out);
      add_shaft_order(out, in, 2, -0.9, [](const InputRow&) { return 650.0; });
    };
    cases.push_back(c);
  }
  return cases;
}

}  // namespace gc::campaign
