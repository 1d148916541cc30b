#include "tests/diagnosis/campaign/programme.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "tests/diagnosis/independent/test_cell_noise.h"

namespace gc::campaign {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

// The state the rig is commanded to; the programme moves it by ramps and holds, sample by sample.
struct Command {
  double torque_nm = 0.2e6;
  double zeta_rad = 0.0;
  double beta_rad = 0.8;
  double speed_rpm = 12.0;
};

class Builder {
 public:
  explicit Builder(const ProgrammeOptions& o) : o_(o), rng_(o.seed * 0x9e3779b97f4a7c15ULL + 17) {
    temperature_ = o.start_temperature_c;
  }

  // Linear ramp of every commanded quantity to `to` over `seconds`.
  void ramp(const Command& to, double seconds) {
    const Command from = c_;
    const int n = std::max(1, static_cast<int>(std::lround(seconds * kSampleRateHz)));
    for (int k = 1; k <= n; ++k) {
      const double f = static_cast<double>(k) / n;
      c_.torque_nm = from.torque_nm + f * (to.torque_nm - from.torque_nm);
      c_.zeta_rad = from.zeta_rad + f * (to.zeta_rad - from.zeta_rad);
      c_.beta_rad = from.beta_rad + f * (to.beta_rad - from.beta_rad);
      c_.speed_rpm = from.speed_rpm + f * (to.speed_rpm - from.speed_rpm);
      emit();
    }
    c_ = to;
  }
  void hold(double seconds) {
    const int n = static_cast<int>(std::lround(seconds * kSampleRateHz));
    for (int k = 0; k < n; ++k) emit();
  }

  // Field-like block: torque an Ornstein-Uhlenbeck process around 1.2 MN·m (turbulence, tau 4 s,
  // sigma 0.18 MN·m) plus a slower 30 s component, misalignment wandering slowly (tau 20 s) as the
  // nacelle deflects, speed following torque loosely (a variable-speed rotor).
  void field(double seconds) {
    const int n = static_cast<int>(std::lround(seconds * kSampleRateHz));
    const double a_fast = std::exp(-kDt / 4.0), a_slow = std::exp(-kDt / 30.0), a_zeta = std::exp(-kDt / 20.0);
    double fast = 0.0, slow = 0.0, wander = 0.0;
    const Command start = c_;
    for (int k = 0; k < n; ++k) {
      fast = a_fast * fast + std::sqrt(1 - a_fast * a_fast) * 0.15e6 * rng_.standard_normal();
      slow = a_slow * slow + std::sqrt(1 - a_slow * a_slow) * 0.10e6 * rng_.standard_normal();
      wander = a_zeta * wander + std::sqrt(1 - a_zeta * a_zeta) * 0.07 * kDeg * rng_.standard_normal();
      // Fade the fluctuations in and out over 10 s, so the block joins its neighbours smoothly.
      const double edge = std::clamp(std::min(k, n - 1 - k) / 100.0, 0.0, 1.0);
      c_.torque_nm = std::clamp(start.torque_nm + edge * (fast + slow), 0.35e6, 2.45e6);
      c_.zeta_rad = std::clamp(start.zeta_rad + edge * wander, 0.03 * kDeg, o_.zeta_max_deg * kDeg);
      c_.speed_rpm = std::clamp(start.speed_rpm + edge * 1.5 * (c_.torque_nm - start.torque_nm) / 0.3e6, 8.0, 15.0);
      emit();
    }
  }

  void pass() {
    const double zmax = o_.zeta_max_deg * kDeg;
    // 1. Torque staircase 0.2 .. 2.5 MN·m at 0.20 deg, beta 0.8 rad, 12 rpm: 4 s ramps, 26 s holds.
    ramp({0.2e6, 0.20 * kDeg, 0.8, 12.0}, 10.0);
    for (double t_mnm : {0.2, 0.4, 0.6, 0.8, 1.0, 1.2, 1.4, 1.6, 1.8, 2.0, 2.2, 2.4, 2.5}) {
      ramp({t_mnm * 1e6, 0.20 * kDeg, 0.8, 12.0}, 4.0);
      hold(26.0);
    }
    // 2. Misalignment sweeps 0 -> zeta_max -> 0 (45 s up, 5 s hold, 45 s down) at beta 0 and
    //    pi/2, at 6 rpm and 1.0 MN·m, then at 12 rpm and 2.0 MN·m.
    for (const auto& [speed, torque] : {std::pair{6.0, 1.0e6}, std::pair{12.0, 2.0e6}}) {
      for (double beta : {0.0, std::numbers::pi / 2}) {
        ramp({torque, 0.0, beta, speed}, 10.0);
        ramp({torque, zmax, beta, speed}, 45.0);
        hold(5.0);
        ramp({torque, 0.0, beta, speed}, 45.0);
      }
    }
    // 3. Field-like stochastic block, 300 s around 1.2 MN·m, 0.25 deg, beta 0.3 rad, 12 rpm.
    ramp({1.2e6, std::min(0.25 * kDeg, 0.8 * zmax), 0.3, 12.0}, 15.0);
    field(300.0);
    // 4. Speed run 3-15-3 rpm at 1.5 MN·m, 0.25 deg, beta pi/2: 120 s up, 120 s down.
    ramp({1.5e6, std::min(0.25 * kDeg, 0.8 * zmax), std::numbers::pi / 2, 3.0}, 20.0);
    ramp({1.5e6, std::min(0.25 * kDeg, 0.8 * zmax), std::numbers::pi / 2, 15.0}, 120.0);
    ramp({1.5e6, std::min(0.25 * kDeg, 0.8 * zmax), std::numbers::pi / 2, 3.0}, 120.0);
    ramp({1.0e6, 0.15 * kDeg, 0.8, 12.0}, 20.0);
  }

  std::vector<InputRow> take() { return std::move(rows_); }
  std::size_t size() const { return rows_.size(); }

 private:
  void emit() {
    InputRow r;
    r.time_s = o_.start_time_s + static_cast<double>(rows_.size()) * kDt;
    r.torque_nm = c_.torque_nm;
    r.zeta_rad = c_.zeta_rad;
    r.beta_rad = c_.beta_rad;
    r.speed_rpm = c_.speed_rpm;
    // Shaft angle: trapezoidal integral of the speed from the recording's start (keyphasor).
    if (!rows_.empty()) {
      phase_ += 0.5 * (rows_.back().speed_rpm + c_.speed_rpm) * (2 * std::numbers::pi / 60.0) * kDt;
    }
    r.phase_rad = phase_;
    // Oil temperature: first-order lag (tau 300 s) towards 35 deg C + 30 deg C at full torque
    // (churning and mesh losses grow with load and speed).
    const double steady = 35.0 + 30.0 * (c_.torque_nm / 2.5e6) * (0.6 + 0.4 * c_.speed_rpm / 15.0);
    temperature_ += (steady - temperature_) * kDt / 300.0;
    r.temperature_c = temperature_;
    rows_.push_back(r);
  }

  ProgrammeOptions o_;
  independent::NoiseStream rng_;
  Command c_;
  double phase_ = 0.0;
  double temperature_ = 35.0;
  std::vector<InputRow> rows_;
};

}  // namespace

std::vector<InputRow> test_programme(const ProgrammeOptions& options) {
  Builder b(options);
  while (b.size() < options.rows) b.pass();
  std::vector<InputRow> rows = b.take();
  rows.resize(options.rows);
  return rows;
}

std::size_t programme_pass_rows() {
  ProgrammeOptions o;
  o.rows = 1;
  Builder b(o);
  b.pass();
  return b.size();
}

}  // namespace gc::campaign
