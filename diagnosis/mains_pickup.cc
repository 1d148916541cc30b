#include "diagnosis/mains_pickup.h"

#include <algorithm>
#include <cmath>

#include "core/effects/expression_terms.h"
#include "diagnosis/time_step.h"
#include "diagnosis/verdict_text.h"

namespace gc {
namespace {

/// Where a wave of `f` [Hz] shows when sampled at `fs` [Hz]: folded into [0, fs / 2].
double aliased(double f, double fs) {
  if (!(fs > 0.0) || !std::isfinite(fs)) return f;
  const double folded = std::fmod(f, fs);
  return folded > 0.5 * fs ? fs - folded : folded;
}

/// The shaft's speeds on `rows` [rpm], each rounded to 0.1 rpm, without repeats; empty when none is
/// recorded.
std::vector<double> recorded_speeds_rpm(std::span<const RecordedSample> observations, const std::vector<std::size_t>& rows) {
  std::vector<double> speeds;
  for (const std::size_t r : rows) {
    if (observations[r].input.speed_rpm) speeds.push_back(std::round(10.0 * std::abs(*observations[r].input.speed_rpm)) / 10.0);
  }
  std::sort(speeds.begin(), speeds.end());
  speeds.erase(std::unique(speeds.begin(), speeds.end()), speeds.end());
  return speeds;
}

/// Whether a shaft or tooth-mesh order of a coupling of `teeth` (orders 1-4, the mesh order and its
/// sidebands N - 2..N + 2, twice the mesh) at one of `speeds_rpm` lies within `tolerance_hz` of
/// `frequency_hz`, directly or aliased by `sample_rate_hz`.
bool near_an_order(double frequency_hz, const std::vector<double>& speeds_rpm, int teeth, double sample_rate_hz,
                   double tolerance_hz) {
  std::vector<int> orders{1, 2, 3, 4};
  if (teeth > 2) {
    for (int k = teeth - 2; k <= teeth + 2; ++k) orders.push_back(k);
    orders.push_back(2 * teeth);
  }
  for (const double rpm : speeds_rpm) {
    for (const int order : orders) {
      if (std::abs(aliased(order * rpm / 60.0, sample_rate_hz) - frequency_hz) <= tolerance_hz) return true;
    }
  }
  return false;
}

/// Whether a line at `frequency_hz` stands out of `residual` (one row per `rows`) on the rows whose
/// speed puts no shaft or mesh order near it (near_an_order at that row's speed), or that have no
/// speed: an order's frequency follows the shaft, so a line of fixed frequency at speeds where no
/// order can be there is the mains'. Least squares of each channel on a level and the cycle's
/// cosine and sine; F of the cycle's two terms over 20 (a white-noise p of 1e-8: a strict test,
/// for the line's frequency already is the mains'). Fewer than 100 such rows say nothing.
bool line_away_from_the_orders(double frequency_hz, const Eigen::MatrixX2d& residual,
                               std::span<const RecordedSample> observations, const std::vector<std::size_t>& rows,
                               int teeth, double sample_rate_hz, double tolerance_hz) {
  std::vector<Eigen::Index> far;
  for (std::size_t k = 0; k < rows.size(); ++k) {
    const std::optional<double>& speed = observations[rows[k]].input.speed_rpm;
    if (!speed || !near_an_order(frequency_hz, {std::round(10.0 * std::abs(*speed)) / 10.0}, teeth, sample_rate_hz,
                                 tolerance_hz)) {
      far.push_back(static_cast<Eigen::Index>(k));
    }
  }
  constexpr std::size_t kFewestRows = 100;
  constexpr double kLeastF = 20.0;
  if (far.size() < kFewestRows || residual.rows() != static_cast<Eigen::Index>(rows.size())) return false;
  const Eigen::Index n = static_cast<Eigen::Index>(far.size());
  Eigen::MatrixXd design(n, 3);
  Eigen::MatrixX2d y(n, 2);
  for (Eigen::Index i = 0; i < n; ++i) {
    const double phase = 2.0 * M_PI * frequency_hz * observations[rows[static_cast<std::size_t>(far[i])]].input.time_s;
    design.row(i) << 1.0, std::cos(phase), std::sin(phase);
    y.row(i) = residual.row(far[i]);
  }
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(design);
  for (int c = 0; c < 2; ++c) {
    const Eigen::VectorXd fitted = design * qr.solve(y.col(c));
    const double rss_level = (y.col(c).array() - y.col(c).mean()).square().sum();
    const double rss_cycle = (y.col(c) - fitted).squaredNorm();
    if (rss_cycle > 0.0 && (rss_level - rss_cycle) / 2.0 / (rss_cycle / static_cast<double>(n - 3)) > kLeastF) return true;
  }
  return false;
}

/// A ringing mode damped less than this is a line of about 2 zeta f_n [Hz] width (0.05: a
/// quality factor of 10).
constexpr double kMostLineDamping = 0.05;

}  // namespace

std::optional<double> mains_frequency(double frequency_hz, double sample_rate_hz, double resolution_hz) {
  for (double base : {50.0, 60.0}) {
    for (int harmonic = 1; harmonic <= 3; ++harmonic) {
      const double mains = harmonic * base;
      const double seen = aliased(mains, sample_rate_hz);
      // A mains frequency aliased onto almost nothing is a drift, which other tests judge.
      if (seen < 2.0 * resolution_hz) continue;
      // The grid's own deviation, 0.5 % of the mains frequency, moves its alias by as many hertz:
      // 0.5 % of the alias was too narrow (60 Hz wandering by 0.16 Hz, sampled at 58.3 Hz, showed
      // at 1.635 Hz for 1.7, and was claimed as a time cycle: noise zoo seed 20261315, draw 251).
      if (std::abs(seen - frequency_hz) <= resolution_hz + 0.005 * mains) return mains;
    }
  }
  return std::nullopt;
}

std::string mains_pickup_text(double cycle_hz, double mains_hz) {
  const std::string at = std::abs(cycle_hz - mains_hz) < 0.01 * mains_hz
                             ? short_number(mains_hz) + " Hz"
                             : short_number(cycle_hz) + " Hz (" + short_number(mains_hz) + " Hz aliased by the sample rate)";
  return "a cycle at " + at + " is mains pickup in the bridges or their cables, an instrument artefact: not offered "
         "as physics (screen and ground the bridge cables, or filter it)";
}

std::string take_out_mains_cycles(std::vector<std::string>& time_terms, std::span<const RecordedSample> observations,
                                  const std::vector<std::size_t>& rows, const Eigen::MatrixX2d& residual, int teeth) {
  if (rows.size() < 2) return "";
  Eigen::VectorXd t(static_cast<Eigen::Index>(rows.size()));
  for (std::size_t k = 0; k < rows.size(); ++k) t(static_cast<Eigen::Index>(k)) = observations[rows[k]].input.time_s;
  const double step = typical_time_step(t);
  const double duration = t(t.size() - 1) - t(0);
  if (!(step > 0.0) || !(duration > 0.0)) return "";
  const std::vector<double> speeds_rpm = recorded_speeds_rpm(observations, rows);
  std::string text;
  std::erase_if(time_terms, [&](const std::string& name) {
    const ExpressionTerm* term = find_expression_term(name);
    if (!term) return false;
    // A lightly damped ringing mode driven by a torque that moves all the time is a narrow line
    // too: 50 Hz pickup on a torque sweep was claimed as the rig ringing at 49.7 and 50.7 Hz with a
    // damping of 0.01 (zoo seed 20261227 draw 71). A rig mode at the mains frequency cannot be told
    // from the pickup, as a cycle there cannot.
    const bool line = term->period_s > 0.0 ||
                      (term->reads_history() && term->ringing.damping_ratio <= kMostLineDamping);
    if (!line) return false;
    const double f = term->period_s > 0.0 ? 1.0 / term->period_s : term->ringing.natural_frequency_hz;
    const std::optional<double> mains = mains_frequency(f, 1.0 / step, 1.0 / duration);
    // An aliased mains line where a shaft or mesh order also shows, at any speed the shaft ran, is
    // left to the physics: 60 Hz at 50 Hz sampling lands at 10 Hz, where a 56-tooth mesh at 10.7 rpm
    // also is, on a staircase of 10-14 rpm. Elsewhere it is mains: 50 Hz sampled at 11 Hz was
    // claimed as a cycle of 5.02 Hz in a zoo draw. A wide speed sweep puts an order near most
    // frequencies at some speed; the line stays with the physics unless it is also there at the
    // speeds where no order is near (60 Hz sampled at 38 Hz, a line at 16.0 Hz on every row of a
    // shaft wandering 6.7-14.2 rpm, where a 100-tooth mesh passes 16 Hz on 15 % of the rows, was
    // claimed as a time cycle: zoo seed 20261225 draw 362).
    const double tolerance = 1.0 / duration + 0.005 * f;
    if (mains && *mains >= 0.5 / step && near_an_order(f, speeds_rpm, teeth, 1.0 / step, tolerance) &&
        !line_away_from_the_orders(f, residual, observations, rows, teeth, 1.0 / step, tolerance)) {
      return false;
    }
    if (mains && text.empty()) text = mains_pickup_text(f, *mains);
    return mains.has_value();
  });
  return text;
}

}  // namespace gc
