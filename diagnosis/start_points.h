// Where the fit of an effect starts: its defaults, its neutral values and a few points of a
// Halton sequence spread over the unit box. Several starts, because directions (beta0, the
// gravity direction) and the induced-moment sawtooth give the cost more than one valley.
#pragma once

#include <vector>

#include <Eigen/Dense>

namespace gc {

/// The first `count` points of the Halton sequence in [0, 1]^dimensions (bases 2, 3, 5, ...),
/// deterministic so a diagnosis is reproducible.
std::vector<Eigen::VectorXd> halton_points(int dimensions, int count);

}  // namespace gc
