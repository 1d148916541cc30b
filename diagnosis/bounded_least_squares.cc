#include "diagnosis/bounded_least_squares.h"

#include <algorithm>
#include <stdexcept>

namespace gc {
namespace {

Eigen::VectorXd clamp_to_box(Eigen::VectorXd x) { return x.cwiseMax(0.0).cwiseMin(1.0); }

/// Central difference where x +- h both lie in the box and evaluate, else one-sided against r.
Eigen::VectorXd difference_column(const ResidualFunction& f, const Eigen::VectorXd& x,
                                  const Eigen::VectorXd& r, Eigen::Index i, double h, int& evaluations) {
  Eigen::VectorXd up = x, down = x;
  up(i) = std::min(1.0, x(i) + h);
  down(i) = std::max(0.0, x(i) - h);
  std::optional<Eigen::VectorXd> r_up, r_down;
  if (up(i) > x(i)) { r_up = f(up); ++evaluations; }
  if (down(i) < x(i)) { r_down = f(down); ++evaluations; }
  if (r_up && r_down) return (*r_up - *r_down) / (up(i) - down(i));
  if (r_up) return (*r_up - r) / (up(i) - x(i));
  if (r_down) return (r - *r_down) / (x(i) - down(i));
  return Eigen::VectorXd::Zero(r.size());  // no evaluable neighbour: the parameter is held
}

/// Parameters free to move this step: not at a bound with the descent direction leaving the box.
std::vector<Eigen::Index> free_parameters(const Eigen::VectorXd& x, const Eigen::VectorXd& gradient) {
  std::vector<Eigen::Index> free;
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    const bool held = (x(i) <= 0.0 && gradient(i) > 0.0) || (x(i) >= 1.0 && gradient(i) < 0.0);
    if (!held) free.push_back(i);
  }
  return free;
}

/// The damped Gauss-Newton step (J'J + lambda diag(J'J)) dx = -J'r on the free parameters.
Eigen::VectorXd damped_step(const Eigen::MatrixXd& normal, const Eigen::VectorXd& gradient,
                            const std::vector<Eigen::Index>& free, double lambda) {
  const auto n = static_cast<Eigen::Index>(free.size());
  Eigen::MatrixXd a(n, n);
  Eigen::VectorXd g(n);
  const double floor = 1e-12 * std::max(1e-300, normal.diagonal().maxCoeff());
  for (Eigen::Index i = 0; i < n; ++i) {
    g(i) = gradient(free[i]);
    for (Eigen::Index k = 0; k < n; ++k) a(i, k) = normal(free[i], free[k]);
    a(i, i) += lambda * (normal(free[i], free[i]) + floor);
  }
  const Eigen::VectorXd reduced = a.ldlt().solve(-g);
  Eigen::VectorXd step = Eigen::VectorXd::Zero(gradient.size());
  for (Eigen::Index i = 0; i < n; ++i) step(free[i]) = reduced(i);
  return step;
}

}  // namespace

Eigen::MatrixXd difference_jacobian(const ResidualFunction& residual, const Eigen::VectorXd& x,
                                    const Eigen::VectorXd& r, double step, int& evaluations) {
  Eigen::MatrixXd jacobian(r.size(), x.size());
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    jacobian.col(i) = difference_column(residual, x, r, i, step, evaluations);
  }
  return jacobian;
}

LeastSquaresResult bounded_least_squares(const ResidualFunction& residual, const Eigen::VectorXd& x0,
                                         const LeastSquaresOptions& options) {
  LeastSquaresResult out;
  out.x = clamp_to_box(x0);
  std::optional<Eigen::VectorXd> r = residual(out.x);
  out.evaluations = 1;
  if (!r) throw std::invalid_argument("bounded_least_squares: the start point cannot be evaluated");
  out.residual = *r;
  out.cost = out.residual.squaredNorm();
  double lambda = 1e-3;
  out.jacobian = difference_jacobian(residual, out.x, out.residual, options.difference_step, out.evaluations);
  while (out.iterations < options.max_iterations && !out.converged) {
    ++out.iterations;
    const Eigen::MatrixXd normal = out.jacobian.transpose() * out.jacobian;
    const Eigen::VectorXd gradient = out.jacobian.transpose() * out.residual;
    const std::vector<Eigen::Index> free = free_parameters(out.x, gradient);
    if (free.empty()) { out.converged = true; break; }
    bool accepted = false;
    for (int attempt = 0; attempt < 8 && !accepted; ++attempt) {
      const Eigen::VectorXd trial_x = clamp_to_box(out.x + damped_step(normal, gradient, free, lambda));
      const std::optional<Eigen::VectorXd> trial = residual(trial_x);
      ++out.evaluations;
      const double trial_cost = trial ? trial->squaredNorm() : out.cost;
      if (trial && trial_cost < out.cost) {
        accepted = true;
        out.converged = out.cost - trial_cost <= options.relative_tolerance * out.cost;
        out.x = trial_x;
        out.residual = *trial;
        out.cost = trial_cost;
        lambda = std::max(1e-7, lambda * 0.3);
      } else {
        lambda *= 4.0;
      }
    }
    if (!accepted) { out.converged = true; break; }  // no descent left at any damping
    out.jacobian = difference_jacobian(residual, out.x, out.residual, options.difference_step, out.evaluations);
  }
  return out;
}

}  // namespace gc
