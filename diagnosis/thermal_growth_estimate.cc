#include "diagnosis/thermal_growth_estimate.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <limits>

#include "diagnosis/effect_fit.h"
#include "diagnosis/model_residuals.h"

namespace gc {
namespace {

constexpr int kLeastRows = 16;
constexpr double kLeastSpanC = 0.5;          ///< a narrower temperature span says nothing of a slope
constexpr double kProbeShareOfJam = 0.01;    ///< the finite difference's step, of the jam angle
constexpr double kLowestC = -40.0, kHighestC = 150.0;  ///< thermal_misalignment's bounds on theta_0
constexpr int kGaussNewtonSteps = 4;

const EffectRegistration* find(const std::vector<EffectRegistration>& library, const std::string& name) {
  const auto it = std::find_if(library.begin(), library.end(),
                               [&](const EffectRegistration& r) { return r.info->name == name; });
  return it == library.end() ? nullptr : &*it;
}

/// A growth as the vector line q (theta - theta_0): q = g along beta_t [rad/degC].
struct Line {
  Eigen::Vector2d q = Eigen::Vector2d::Zero();
  double theta0 = 0.0;  ///< [degC]
  ParameterValues values() const {
    return {{"growth_rad_per_c", q.norm()}, {"reference_temperature_c", theta0}, {"direction_rad", std::atan2(q(1), q(0))}};
  }
};

/// On the rows with a temperature that every model predicts: the residual and the moments'
/// response to a unit vector along y' and z' [N·m/rad], stacked as the channels (i, then m + i).
struct Linearised {
  Eigen::VectorXd residual, along_y, along_z, theta;
  double sum_of_squares() const { return residual.squaredNorm(); }
};

std::optional<Linearised> linearise(const CouplingModel& model, const EffectRegistration& offset,
                                    std::span<const RecordedSample> observations, std::span<const std::size_t> rows,
                                    const ParallelFor& parallel) {
  const double step = kProbeShareOfJam * model.geometry().jam_angle().angle_rad;  // [rad]
  const ModelResiduals at = model_residuals(model, observations, rows, parallel);
  const ModelResiduals y = model_residuals(model_with(model, offset, {{"zeta0_rad", step}, {"beta0_rad", 0.0}}),
                                           observations, rows, parallel);
  const ModelResiduals z = model_residuals(model_with(model, offset, {{"zeta0_rad", step}, {"beta0_rad", M_PI / 2}}),
                                           observations, rows, parallel);
  std::vector<std::size_t> failed = at.failed_rows;
  failed.insert(failed.end(), y.failed_rows.begin(), y.failed_rows.end());
  failed.insert(failed.end(), z.failed_rows.begin(), z.failed_rows.end());
  std::sort(failed.begin(), failed.end());
  std::vector<Eigen::Index> kept;
  for (std::size_t k = 0; k < rows.size(); ++k) {
    if (observations[rows[k]].input.temperature_c && !std::binary_search(failed.begin(), failed.end(), rows[k])) {
      kept.push_back(static_cast<Eigen::Index>(k));
    }
  }
  const Eigen::Index m = static_cast<Eigen::Index>(kept.size());
  if (m < kLeastRows) return std::nullopt;
  Linearised out{Eigen::VectorXd(2 * m), Eigen::VectorXd(2 * m), Eigen::VectorXd(2 * m), Eigen::VectorXd(m)};
  for (Eigen::Index i = 0; i < m; ++i) {
    const Eigen::Index k = kept[i];
    out.theta(i) = *observations[rows[static_cast<std::size_t>(k)]].input.temperature_c;
    for (int c = 0; c < 2; ++c) {
      out.residual(c * m + i) = at.residual(k, c);
      out.along_y(c * m + i) = (at.residual(k, c) - y.residual(k, c)) / step;
      out.along_z(c * m + i) = (at.residual(k, c) - z.residual(k, c)) / step;
    }
  }
  return out;
}

/// Least squares of the residual on `columns` of the responses: a vector's own step (a, 2
/// columns), or the vector's step and its slope in temperature about `mean_c` (a, b: 4 columns).
std::optional<Eigen::VectorXd> regress(const Linearised& l, int columns, double mean_c) {
  const Eigen::Index m = l.theta.size();
  Eigen::MatrixXd design(2 * m, columns);
  for (Eigen::Index r = 0; r < 2 * m; ++r) {
    design(r, 0) = l.along_y(r);
    design(r, 1) = l.along_z(r);
    if (columns == 4) {
      const double tau = l.theta(r % m) - mean_c;
      design(r, 2) = l.along_y(r) * tau;
      design(r, 3) = l.along_z(r) * tau;
    }
  }
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(design);
  if (qr.rank() < columns) return std::nullopt;
  Eigen::VectorXd c = qr.solve(l.residual);
  return c.allFinite() ? std::optional(c) : std::nullopt;
}

/// A Gauss-Newton step of (q, theta_0) about `line`, linearised at the model with it: the moments
/// move by J (theta - theta_0) dq - J q dtheta_0.
std::optional<Eigen::Vector3d> line_step(const Line& line, const Linearised& l) {
  const Eigen::Index m = l.theta.size();
  Eigen::MatrixXd design(2 * m, 3);
  for (Eigen::Index r = 0; r < 2 * m; ++r) {
    const double rise = l.theta(r % m) - line.theta0;
    design.row(r) << l.along_y(r) * rise, l.along_z(r) * rise, -(l.along_y(r) * line.q(0) + l.along_z(r) * line.q(1));
  }
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(design);
  if (qr.rank() < 3) return std::nullopt;
  const Eigen::Vector3d d = qr.solve(l.residual);
  return d.allFinite() ? std::optional(d) : std::nullopt;
}

/// Gauss-Newton from `x` with `at(x)` the linearisation there (nullopt: not predictable) and
/// `step(x, l)` the step it proposes; a step that does not lower the sum of squares is halved, up
/// to three times. Returns the best point and its linearisation.
template <class X, class At, class Step>
std::pair<X, std::optional<Linearised>> descend(X x, At at, Step step, int steps) {
  std::optional<Linearised> here = at(x);
  for (int s = 0; s < steps && here; ++s) {
    const std::optional<X> dx = step(x, *here);
    if (!dx) break;
    bool moved = false;
    for (double share = 1.0; share >= 0.125 && !moved; share /= 2.0) {
      const X next = x + share * *dx;
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

}  // namespace

std::optional<ParameterValues> thermal_growth_estimate(const CouplingModel& model,
                                                       std::span<const RecordedSample> observations,
                                                       std::span<const std::size_t> rows,
                                                       const std::vector<EffectRegistration>& library,
                                                       const ParallelFor& parallel) {
  const EffectRegistration* offset = find(library, "assembly_misalignment");
  const EffectRegistration* growth = find(library, "thermal_misalignment");
  if (!offset || !growth) return std::nullopt;
  const auto at_vector = [&](const Eigen::Vector2d& a) {
    return linearise(model_with(model, *offset, {{"zeta0_rad", a.norm()}, {"beta0_rad", std::atan2(a(1), a(0))}}),
                     *offset, observations, rows, parallel);
  };
  // A vector of the size of the measured misalignment bends the moments' response: first the
  // constant vector the residual asks for, by Gauss-Newton from none.
  auto [a, at_a] = descend(
      Eigen::Vector2d(Eigen::Vector2d::Zero()), at_vector,
      [](const Eigen::Vector2d&, const Linearised& l) -> std::optional<Eigen::Vector2d> {
        const std::optional<Eigen::VectorXd> c = regress(l, 2, 0.0);
        return c ? std::optional<Eigen::Vector2d>(c->head<2>()) : std::nullopt;
      },
      kGaussNewtonSteps);
  if (!at_a || at_a->theta.maxCoeff() - at_a->theta.minCoeff() < kLeastSpanC) return std::nullopt;
  // There, its slope in temperature; the line through both is where the growth starts.
  const double mean_c = at_a->theta.mean();
  const std::optional<Eigen::VectorXd> c = regress(*at_a, 4, mean_c);
  if (!c) return std::nullopt;
  const Eigen::Vector2d here = a + c->head<2>(), b = c->tail<2>();
  if (!(b.norm() > 0.0)) return std::nullopt;
  const Line first{b, std::clamp(mean_c - here.dot(b) / b.squaredNorm(), kLowestC, kHighestC)};
  // Then the line itself, in (q, theta_0).
  const auto at_line = [&](const Eigen::Vector3d& x) {
    const Line line{x.head<2>(), std::clamp(x(2), kLowestC, kHighestC)};
    return linearise(model_with(model, *growth, line.values()), *offset, observations, rows, parallel);
  };
  const auto [x, at_x] = descend(
      Eigen::Vector3d(first.q(0), first.q(1), first.theta0), at_line,
      [](const Eigen::Vector3d& x, const Linearised& l) { return line_step(Line{x.head<2>(), x(2)}, l); },
      kGaussNewtonSteps);
  if (!at_x) return std::nullopt;
  const Line kept{x.head<2>(), std::clamp(x(2), kLowestC, kHighestC)};
  return kept.values();
}

}  // namespace gc
