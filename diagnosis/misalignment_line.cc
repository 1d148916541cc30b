#include "diagnosis/misalignment_line.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <string>

#include "core/restoring_torque.h"
#include "diagnosis/effect_fit.h"
#include "diagnosis/model_residuals.h"

namespace gc {
namespace {

constexpr int kLeastRows = 16;
/// The finite differences' steps, of the jam angle. The moments' sums step with the teeth in
/// contact (eqs 13, 42-43): over a hundredth of the jam angle a difference follows the steps (a
/// sag's slope in torque came out a third of the truth, WeakEffectStarts tests), and over a tenth
/// it is a secant across the response's curvature where the vector is a fair share of the measured
/// misalignment (a growth's start from it stopped short of the truth, zoo power seed 20261267 draw
/// 0). A line is found at each, and the fit starts from whichever costs less (best_starts).
constexpr double kProbeSharesOfJam[] = {0.01, 0.1};
/// The step of the surrogate test's design (misalignment_line_design): a secant, smooth.
constexpr double kDesignShareOfJam = 0.1;
constexpr int kGaussNewtonSteps = 4;

const EffectRegistration* find(const std::vector<EffectRegistration>& library, const std::string& name) {
  const auto it = std::find_if(library.begin(), library.end(),
                               [&](const EffectRegistration& r) { return r.info->name == name; });
  return it == library.end() ? nullptr : &*it;
}

/// `values` within `info`'s physical bounds: a line far from the truth (a step of Gauss-Newton, a
/// slope the noise gave) must still make an effect (make_effect refuses a value out of bounds).
ParameterValues within_bounds(const EffectInfo& info, ParameterValues values) {
  for (const ParameterSpec& spec : info.parameters) {
    if (const auto it = values.find(spec.name); it != values.end()) it->second = std::clamp(it->second, spec.lower, spec.upper);
  }
  return values;
}

/// The vector line q (x - x0): q [rad per unit of x] along its direction, x0 [unit of x].
struct Line {
  Eigen::Vector2d q = Eigen::Vector2d::Zero();
  double x0 = 0.0;
};

/// What the line runs along, and what it may be.
struct LineInput {
  std::function<std::optional<double>(const MeasurementSample&)> x;
  double least_span;       ///< a narrower span of x says nothing of a slope [unit of x]
  double lowest, highest;  ///< the bounds on x0 [unit of x]
};

/// On the rows with an x that every model predicts: the residual and the moments' response to a
/// unit vector along y' and z' [N·m/rad], stacked as the channels (i, then m + i).
struct Linearised {
  Eigen::VectorXd residual, along_y, along_z, x;
  double sum_of_squares() const { return residual.squaredNorm(); }
};

/// `model` with a constant vector a [rad] added to the measured misalignment.
CouplingModel with_vector(const CouplingModel& model, const Eigen::Vector2d& a) {
  return model.with_effect(make_effect("assembly_misalignment", {{"zeta0_rad", a.norm()}, {"beta0_rad", std::atan2(a(1), a(0))}}));
}

/// The finite difference's step [rad].
double probe_step(const CouplingModel& model, double share) { return share * model.geometry().jam_angle().angle_rad; }

/// `model`'s residuals, and with a small vector along y' and along z' (beta = 0, pi/2).
struct Probes {
  ModelResiduals at, y, z;
};

Probes probes(const CouplingModel& model, double step, std::span<const RecordedSample> observations,
              std::span<const std::size_t> rows, const ParallelFor& parallel) {
  return {model_residuals(model, observations, rows, parallel),
          model_residuals(with_vector(model, {step, 0.0}), observations, rows, parallel),
          model_residuals(with_vector(model, {0.0, step}), observations, rows, parallel)};
}

std::optional<Linearised> linearise(const CouplingModel& model, double step, std::span<const RecordedSample> observations,
                                    std::span<const std::size_t> rows, const LineInput& input, const ParallelFor& parallel) {
  const auto [at, y, z] = probes(model, step, observations, rows, parallel);
  std::vector<std::size_t> failed = at.failed_rows;
  failed.insert(failed.end(), y.failed_rows.begin(), y.failed_rows.end());
  failed.insert(failed.end(), z.failed_rows.begin(), z.failed_rows.end());
  std::sort(failed.begin(), failed.end());
  std::vector<Eigen::Index> kept;
  for (std::size_t k = 0; k < rows.size(); ++k) {
    if (input.x(observations[rows[k]].input) && !std::binary_search(failed.begin(), failed.end(), rows[k])) {
      kept.push_back(static_cast<Eigen::Index>(k));
    }
  }
  const Eigen::Index m = static_cast<Eigen::Index>(kept.size());
  if (m < kLeastRows) return std::nullopt;
  Linearised out{Eigen::VectorXd(2 * m), Eigen::VectorXd(2 * m), Eigen::VectorXd(2 * m), Eigen::VectorXd(m)};
  for (Eigen::Index i = 0; i < m; ++i) {
    const Eigen::Index k = kept[i];
    out.x(i) = *input.x(observations[rows[static_cast<std::size_t>(k)]].input);
    for (int c = 0; c < 2; ++c) {
      out.residual(c * m + i) = at.residual(k, c);
      out.along_y(c * m + i) = (at.residual(k, c) - y.residual(k, c)) / step;
      out.along_z(c * m + i) = (at.residual(k, c) - z.residual(k, c)) / step;
    }
  }
  return out;
}

/// Least squares of the residual on the responses: a vector's own step (a: 2 columns), or the
/// vector's step and its slope in x about `mean` (a, b: 4 columns).
std::optional<Eigen::VectorXd> regress(const Linearised& l, int columns, double mean) {
  const Eigen::Index m = l.x.size();
  Eigen::MatrixXd design(2 * m, columns);
  for (Eigen::Index r = 0; r < 2 * m; ++r) {
    design(r, 0) = l.along_y(r);
    design(r, 1) = l.along_z(r);
    if (columns == 4) {
      const double tau = l.x(r % m) - mean;
      design(r, 2) = l.along_y(r) * tau;
      design(r, 3) = l.along_z(r) * tau;
    }
  }
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(design);
  if (qr.rank() < columns) return std::nullopt;
  Eigen::VectorXd c = qr.solve(l.residual);
  return c.allFinite() ? std::optional(c) : std::nullopt;
}

/// A Gauss-Newton step of (q, x0) about `line`, linearised at the model with it: the moments move
/// by J (x - x0) dq - J q dx0.
std::optional<Eigen::VectorXd> line_step(const Line& line, const Linearised& l) {
  const Eigen::Index m = l.x.size();
  Eigen::MatrixXd design(2 * m, 3);
  for (Eigen::Index r = 0; r < 2 * m; ++r) {
    const double rise = l.x(r % m) - line.x0;
    design.row(r) << l.along_y(r) * rise, l.along_z(r) * rise, -(l.along_y(r) * line.q(0) + l.along_z(r) * line.q(1));
  }
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(design);
  if (qr.rank() < 3) return std::nullopt;
  Eigen::VectorXd d = qr.solve(l.residual);
  return d.allFinite() ? std::optional(d) : std::nullopt;
}

/// Gauss-Newton from `x` with `at(x)` the linearisation there (nullopt: not predictable) and
/// `step(x, l)` the step it proposes; a step that does not lower the sum of squares is halved, up
/// to three times. Returns the best point and its linearisation.
template <class At, class Step>
std::pair<Eigen::VectorXd, std::optional<Linearised>> descend(Eigen::VectorXd x, At at, Step step) {
  std::optional<Linearised> here = at(x);
  for (int s = 0; s < kGaussNewtonSteps && here; ++s) {
    const std::optional<Eigen::VectorXd> dx = step(x, *here);
    if (!dx) break;
    bool moved = false;
    for (double share = 1.0; share >= 0.125 && !moved; share /= 2.0) {
      const Eigen::VectorXd next = x + share * *dx;
      std::optional<Linearised> there = at(next);
      if (there && there->sum_of_squares() < here->sum_of_squares()) {
        x = next;
        here = std::move(there);
        moved = true;
      }
    }
    if (!moved) break;
  }
  return {x, here};
}

/// The line in `input` that brings `model` with `with_line(line)` nearest the measured moments.
std::optional<Line> misalignment_line(const CouplingModel& model, double step, std::span<const RecordedSample> observations,
                                      std::span<const std::size_t> rows, const LineInput& input,
                                      const std::function<CouplingModel(const Line&)>& with_line,
                                      const ParallelFor& parallel) {
  const auto at_vector = [&](const Eigen::VectorXd& a) {
    return linearise(with_vector(model, a), step, observations, rows, input, parallel);
  };
  const auto [a, at_a] = descend(Eigen::VectorXd::Zero(2), at_vector, [](const Eigen::VectorXd&, const Linearised& l) {
    return regress(l, 2, 0.0);
  });
  if (!at_a || at_a->x.maxCoeff() - at_a->x.minCoeff() < input.least_span) return std::nullopt;
  const double mean = at_a->x.mean();
  const std::optional<Eigen::VectorXd> c = regress(*at_a, 4, mean);
  if (!c) return std::nullopt;
  const Eigen::Vector2d here = a + c->head<2>(), b = c->tail<2>();
  if (!(b.norm() > 0.0)) return std::nullopt;
  const auto clamped = [&](const Eigen::VectorXd& x) { return Line{x.head<2>(), std::clamp(x(2), input.lowest, input.highest)}; };
  const Eigen::Vector3d first(b(0), b(1), std::clamp(mean - here.dot(b) / b.squaredNorm(), input.lowest, input.highest));
  const auto [x, at_x] = descend(
      first,
      [&](const Eigen::VectorXd& x) {
        return linearise(with_line(clamped(x)), step, observations, rows, input, parallel);
      },
      [&](const Eigen::VectorXd& x, const Linearised& l) { return line_step(clamped(x), l); });
  if (!at_x) return std::nullopt;
  return clamped(x);
}

LineInput temperature_line() {
  return {[](const MeasurementSample& s) { return s.temperature_c; }, 0.5, -40.0, 150.0};
}

LineInput torque_line(double t_m) {
  return {[](const MeasurementSample& s) { return std::optional(s.torque_nm); }, 0.05 * t_m, 0.2 * t_m, 3.0 * t_m};
}

}  // namespace

std::vector<ParameterValues> thermal_growth_starts(const CouplingModel& model, std::span<const RecordedSample> observations,
                                                    std::span<const std::size_t> rows,
                                                    const std::vector<EffectRegistration>& library,
                                                    const ParallelFor& parallel) {
  const EffectRegistration* growth = find(library, "thermal_misalignment");
  if (!growth) return {};
  const auto values = [growth](const Line& line) {
    return within_bounds(*growth->info, {{"growth_rad_per_c", line.q.norm()},
                                         {"reference_temperature_c", line.x0},
                                         {"direction_rad", std::atan2(line.q(1), line.q(0))}});
  };
  std::vector<ParameterValues> out;
  for (const double share : kProbeSharesOfJam) {
    const std::optional<Line> line =
        misalignment_line(model, probe_step(model, share), observations, rows, temperature_line(),
                          [&](const Line& l) { return model_with(model, *growth, values(l)); }, parallel);
    if (line) out.push_back(values(*line));
  }
  return out;
}

std::vector<ParameterValues> eccentricity_starts(const CouplingModel& model, std::span<const RecordedSample> observations,
                                                  std::span<const std::size_t> rows,
                                                  const std::vector<EffectRegistration>& library,
                                                  const ParallelFor& parallel) {
  const EffectRegistration* sag = find(library, "eccentricity");
  if (!sag) return {};
  const double t_m = restoring_torque(model.geometry()).torque_nm;  // eqs 49-53 [N·m]
  // zeta_e (1 - T / x0) along gravity = q (T - x0) with q = -zeta_e / x0 along gravity.
  const auto values = [sag, t_m](const Line& line) {
    return within_bounds(*sag->info, {{"eccentric_misalignment_rad", line.q.norm() * line.x0},
                                      {"threshold_scale", line.x0 / t_m},
                                      {"gravity_direction_rad", std::atan2(-line.q(1), -line.q(0))}});
  };
  std::vector<ParameterValues> out;
  for (const double share : kProbeSharesOfJam) {
    const std::optional<Line> line =
        misalignment_line(model, probe_step(model, share), observations, rows, torque_line(t_m),
                          [&](const Line& l) { return model_with(model, *sag, values(l)); }, parallel);
    if (line) out.push_back(values(*line));
  }
  return out;
}

std::optional<Eigen::MatrixXd> misalignment_line_design(const std::string& effect, const CouplingModel& model,
                                                       std::span<const RecordedSample> observations,
                                                       std::span<const std::size_t> rows, const ParallelFor& parallel) {
  std::optional<LineInput> input;
  if (effect == "thermal_misalignment") input = temperature_line();
  if (effect == "eccentricity") input = torque_line(restoring_torque(model.geometry()).torque_nm);
  if (!input) return std::nullopt;
  const double step = probe_step(model, kDesignShareOfJam);
  const auto [at, y, z] = probes(model, step, observations, rows, parallel);
  if (!at.failed_rows.empty() || !y.failed_rows.empty() || !z.failed_rows.empty()) return std::nullopt;
  const Eigen::Index n = static_cast<Eigen::Index>(rows.size());
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
  Eigen::Index with_x = 0;
  double mean = 0.0;
  for (Eigen::Index k = 0; k < n; ++k) {
    if (const std::optional<double> v = input->x(observations[rows[static_cast<std::size_t>(k)]].input)) {
      x(k) = *v;
      mean += *v;
      ++with_x;
    }
  }
  if (with_x == 0) return std::nullopt;
  mean /= static_cast<double>(with_x);
  Eigen::MatrixXd design = Eigen::MatrixXd::Zero(2 * n, 4);
  for (Eigen::Index k = 0; k < n; ++k) {
    if (!input->x(observations[rows[static_cast<std::size_t>(k)]].input)) continue;  // the effect leaves it alone
    for (int c = 0; c < 2; ++c) {
      const double j_y = (at.residual(k, c) - y.residual(k, c)) / step, j_z = (at.residual(k, c) - z.residual(k, c)) / step;
      design.row(c * n + k) << j_y, j_z, j_y * (x(k) - mean), j_z * (x(k) - mean);
    }
  }
  return design;
}

}  // namespace gc
