#include "tests/diagnosis/zoo/programme.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace gc::zoo {
namespace {

struct State {
  double torque_nm, zeta_rad, beta_rad, speed_rpm;
};

class Builder {
 public:
  Builder(std::size_t rows, const ProgrammeLimits& l, Rng& rng) : l_(l), rng_(rng), forced_(l.first_block) {
    c_.reserve(rows);
    s_ = {draw_torque(), draw_zeta(), draw_beta(), draw_speed()};
  }
  double draw_torque() { return rng_.uniform(l_.torque_min_nm, l_.torque_max_nm); }
  double draw_zeta() { return rng_.uniform(l_.zeta_min_rad, l_.zeta_max_rad); }
  double draw_beta() { return rng_.uniform(-std::numbers::pi, std::numbers::pi); }
  double draw_speed() { return rng_.uniform(l_.speed_min_rpm, l_.speed_max_rpm); }

  void emit() { c_.push_back(s_); }
  // Linear ramp of every quantity from the current state to `to` over n rows.
  void ramp(const State& to, std::size_t n) {
    const State from = s_;
    for (std::size_t k = 1; k <= n; ++k) {
      const double f = static_cast<double>(k) / static_cast<double>(n);
      s_ = {from.torque_nm + f * (to.torque_nm - from.torque_nm), from.zeta_rad + f * (to.zeta_rad - from.zeta_rad),
            from.beta_rad + f * (to.beta_rad - from.beta_rad), from.speed_rpm + f * (to.speed_rpm - from.speed_rpm)};
      emit();
    }
    s_ = to;
  }
  void hold(std::size_t n) {
    for (std::size_t k = 0; k < n; ++k) emit();
  }
  // One block of n rows; returns its name.
  std::string block(std::size_t n) {
    const std::size_t join = std::max<std::size_t>(1, static_cast<std::size_t>(rng_.uniform(0.05, 0.15) * n));
    const std::size_t body = n - std::min(n, join);
    const bool same_speed = rng_.chance(0.5) && !l_.vary_speed;
    const double speed_end = same_speed ? s_.speed_rpm : draw_speed();
    State start{draw_torque(), draw_zeta(), rng_.chance(0.6) ? s_.beta_rad : draw_beta(), draw_speed()};
    int kind = rng_.integer(0, 5);
    const bool forced = forced_ >= 0;
    if (forced) kind = forced_, forced_ = -1;
    if (kind == 1) start.zeta_rad = l_.zeta_min_rad;  // a sweep starts low
    ramp(start, join);
    const double speed0 = s_.speed_rpm;
    auto speed_at = [&](std::size_t k) { return speed0 + (speed_end - speed0) * static_cast<double>(k) / std::max<std::size_t>(1, body); };
    std::size_t k = 0;
    auto step_to = [&](State to, std::size_t m) {
      to.speed_rpm = speed_at(k + m);
      ramp(to, m);
      k += m;
    };
    switch (kind) {
      case 0: {  // staircase of torque or misalignment
        const bool torque = rng_.chance(0.6) || forced;
        const int levels = rng_.integer(3, 12);
        std::vector<double> v(levels);
        for (int j = 0; j < levels; ++j) {
          const double f = (j + 0.5) / levels;
          v[j] = torque ? l_.torque_min_nm + f * (l_.torque_max_nm - l_.torque_min_nm) : l_.zeta_min_rad + f * (l_.zeta_max_rad - l_.zeta_min_rad);
        }
        const int order = rng_.integer(0, 2);
        if (order == 1) std::reverse(v.begin(), v.end());
        if (order == 2) for (int j = levels - 1; j > 0; --j) std::swap(v[j], v[rng_.integer(0, j)]);
        const double ramp_share = rng_.uniform(0.1, 0.25);
        for (int j = 0; j < levels; ++j) {
          const std::size_t m = body / levels, r = std::max<std::size_t>(1, static_cast<std::size_t>(ramp_share * m));
          State to = s_;
          (torque ? to.torque_nm : to.zeta_rad) = v[j];
          step_to(to, r);
          step_to(s_, m > r ? m - r : 1);
        }
        tail(body, k, speed_at);
        return torque ? "staircase(T)" : "staircase(zeta)";
      }
      case 1: {  // misalignment sweeps up and down
        const int cycles = rng_.integer(1, 3);
        const double top = rng_.uniform(0.5, 1.0) * l_.zeta_max_rad;
        for (int j = 0; j < cycles; ++j) {
          const std::size_t m = body / (2 * cycles);
          State up = s_;
          up.zeta_rad = std::max(top, l_.zeta_min_rad);
          step_to(up, std::max<std::size_t>(1, m));
          State down = s_;
          down.zeta_rad = l_.zeta_min_rad;
          step_to(down, std::max<std::size_t>(1, m));
        }
        tail(body, k, speed_at);
        return "sweep(zeta)";
      }
      case 2: {  // a ramp of torque and misalignment
        step_to({draw_torque(), draw_zeta(), s_.beta_rad, 0}, std::max<std::size_t>(1, body));
        return "ramp";
      }
      case 3: {  // random OU block around the start (field-like loads)
        const double tau = std::max(2.0, rng_.uniform(0.02, 0.2) * body), a = std::exp(-1.0 / tau);
        const double sd_t = rng_.uniform(0.05, 0.2) * (l_.torque_max_nm - l_.torque_min_nm);
        const double sd_z = rng_.uniform(0.05, 0.2) * (l_.zeta_max_rad - l_.zeta_min_rad);
        const double sd_b = rng_.uniform(0.0, 0.2);
        double ut = 0, uz = 0, ub = 0;
        const State c = s_;
        for (std::size_t j = 0; j < body; ++j, ++k) {
          const double e = std::clamp(std::min(j, body - 1 - j) / (0.1 * body + 1), 0.0, 1.0);  // fade in and out
          ut = a * ut + std::sqrt(1 - a * a) * rng_.normal();
          uz = a * uz + std::sqrt(1 - a * a) * rng_.normal();
          ub = a * ub + std::sqrt(1 - a * a) * rng_.normal();
          s_ = {std::clamp(c.torque_nm + e * sd_t * ut, l_.torque_min_nm, l_.torque_max_nm),
                std::clamp(c.zeta_rad + e * sd_z * uz, l_.zeta_min_rad, l_.zeta_max_rad), c.beta_rad + e * sd_b * ub, speed_at(k)};
          emit();
        }
        return "ou";
      }
      case 4: {  // the misalignment direction turned slowly
        State to = s_;
        to.beta_rad = s_.beta_rad + rng_.uniform(-std::numbers::pi, std::numbers::pi);
        step_to(to, std::max<std::size_t>(1, body));
        return "turn(beta)";
      }
      default:
        step_to(s_, std::max<std::size_t>(1, body));
        return "hold";
    }
  }
  template <typename F>
  void tail(std::size_t body, std::size_t& k, F speed_at) {
    while (k < body) {
      State to = s_;
      to.speed_rpm = speed_at(k + 1);
      ramp(to, 1);
      ++k;
    }
  }
  std::vector<State>& rows() { return c_; }

 private:
  const ProgrammeLimits& l_;
  Rng& rng_;
  int forced_ = -1;
  State s_;
  std::vector<State> c_;
};

}  // namespace

Programme draw_programme(std::size_t rows, double fs_hz, const ProgrammeLimits& limits, Rng& rng) {
  Builder b(rows, limits, rng);
  const int blocks = rng.integer(1, static_cast<int>(std::clamp<std::size_t>(rows / 300, 1, 6)));
  std::vector<double> w(blocks);
  double sum = 0;
  for (double& x : w) sum += (x = rng.uniform(0.3, 1.0));
  Programme p;
  for (int j = 0; j < blocks; ++j) {
    const std::size_t n = j + 1 == blocks ? rows - std::min(rows, b.rows().size())
                                          : static_cast<std::size_t>(w[j] / sum * static_cast<double>(rows));
    if (n == 0) continue;
    p.description += (p.description.empty() ? "" : ">") + b.block(n);
  }
  auto& s = b.rows();
  s.resize(rows, s.empty() ? State{limits.torque_min_nm, limits.zeta_min_rad, 0, limits.speed_min_rpm} : s.back());
  Channels& c = p.truth;
  c.resize(rows);
  const double t0 = rng.chance(0.5) ? 0.0 : std::round(rng.uniform(0.0, 3600.0));
  const double tau_s = rng.uniform(0.05, 0.3) * static_cast<double>(rows) / fs_hz;
  double temp = rng.uniform(25.0, 45.0);
  for (std::size_t i = 0; i < rows; ++i) {
    c.time_s[i] = t0 + static_cast<double>(i) / fs_hz;
    c.torque_nm[i] = s[i].torque_nm;
    c.zeta_rad[i] = s[i].zeta_rad;
    c.beta_rad[i] = s[i].beta_rad;
    c.speed_rpm[i] = s[i].speed_rpm;
    const double target = 30.0 + 30.0 * s[i].torque_nm / limits.torque_max_nm * (0.6 + 0.4 * s[i].speed_rpm / 15.0);
    temp += (target - temp) * std::min(1.0, 1.0 / (fs_hz * tau_s));
    c.temperature_c[i] = temp;
  }
  return p;
}

}  // namespace gc::zoo
