// A derivative-free polish after Levenberg-Marquardt. The induced-moment sums (eqs 42-43) make
// the cost a rough function of parameters that move the tooth pattern (spacing errors,
// misalignment offsets): finite-difference steps can stall on a tooth of the saw. A compass
// search (try +-step on each coordinate, halve the step when nothing improves) walks past them.
#pragma once

#include "diagnosis/bounded_least_squares.h"

namespace gc {

/// Improves `start` (already evaluated at `start.x`) within the unit box; steps from
/// `initial_step` down to `final_step`, at most `max_evaluations` residual evaluations.
LeastSquaresResult pattern_search(const ResidualFunction& residual, LeastSquaresResult start,
                                  double initial_step, double final_step, int max_evaluations);

}  // namespace gc
