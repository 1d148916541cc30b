#include "diagnosis/pattern_search.h"

#include <algorithm>

namespace gc {

LeastSquaresResult pattern_search(const ResidualFunction& residual, LeastSquaresResult start,
                                  double initial_step, double final_step, int max_evaluations) {
  LeastSquaresResult best = std::move(start);
  int evaluations = 0;
  for (double step = initial_step; step >= final_step && evaluations < max_evaluations;) {
    bool improved = false;
    for (Eigen::Index i = 0; i < best.x.size() && evaluations < max_evaluations; ++i) {
      for (double sign : {+1.0, -1.0}) {
        Eigen::VectorXd x = best.x;
        x(i) = std::clamp(x(i) + sign * step, 0.0, 1.0);
        if (x(i) == best.x(i)) continue;
        const std::optional<Eigen::VectorXd> r = residual(x);
        ++evaluations;
        if (r && r->squaredNorm() < best.cost) {
          best.x = x;
          best.residual = *r;
          best.cost = r->squaredNorm();
          improved = true;
          break;
        }
      }
    }
    if (!improved) step *= 0.5;
  }
  best.evaluations += evaluations;
  return best;
}

}  // namespace gc
