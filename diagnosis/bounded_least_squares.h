// Levenberg-Marquardt for bound-constrained nonlinear least squares on the unit box, with a
// finite-difference Jacobian. The diagnosis scales every effect parameter to [0, 1] by its
// physical bounds, so one step size and one damping rule fit all parameters.
#pragma once

#include <functional>
#include <optional>

#include <Eigen/Dense>

namespace gc {

/// Residual vector at x in [0, 1]^p; nullopt where the model cannot be evaluated there.
using ResidualFunction = std::function<std::optional<Eigen::VectorXd>(const Eigen::VectorXd&)>;

struct LeastSquaresOptions {
  int max_iterations = 10;
  /// Finite-difference step in the unit box. Large on purpose: the induced-moment sums (eqs
  /// 42-43) put a sawtooth of a few % on the moments, and a step much shorter than its period
  /// would follow the teeth of the saw instead of the trend.
  double difference_step = 5e-3;
  /// Stop when a step lowers the cost by less than this share: with noise, the cost's last
  /// 1e-5 moves a parameter by a small fraction of its standard error.
  double relative_tolerance = 1e-5;
};

struct LeastSquaresResult {
  Eigen::VectorXd x;          ///< in [0, 1]^p
  Eigen::VectorXd residual;   ///< at x
  Eigen::MatrixXd jacobian;   ///< d residual / d x at x (central differences inside the box)
  double cost = 0.0;          ///< sum of squared residuals at x
  int iterations = 0;
  int evaluations = 0;
  bool converged = false;
};

/// Minimises |r(x)|^2 over the unit box from x0 (which must be evaluable: throws
/// std::invalid_argument otherwise). Parameters at a bound with the gradient pushing outward
/// are held there for the step (a projected, active-set Levenberg-Marquardt step).
LeastSquaresResult bounded_least_squares(const ResidualFunction& residual, const Eigen::VectorXd& x0,
                                         const LeastSquaresOptions& options = {});

/// The finite-difference Jacobian alone (central inside the box, one-sided at a bound).
Eigen::MatrixXd difference_jacobian(const ResidualFunction& residual, const Eigen::VectorXd& x,
                                    const Eigen::VectorXd& r, double step, int& evaluations);

}  // namespace gc
