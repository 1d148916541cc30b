// A correction as slow as the noise's wander must stand out of it. Within one recording a slow
// effect (a thermal growth that follows the oil temperature, an offset that follows a torque
// staircase) and a zero that wanders with it are the same thing: only its size against the wander
// tells them apart. The formula's slow terms pass this test term by term (formula_search.h); an
// effect passes it as a whole: on a random walk a thermal misalignment took 9 % of the error at t = 4,
// following the walk through the temperature.
#pragma once

#include <Eigen/Dense>

namespace gc {

/// The share of a series' variance (rows in time order, both channels pooled) that its means over
/// kWanderBlocks contiguous blocks carry: about 1 / (rows per block) for white noise, near 1 for a
/// correction that changes only slowly.
double slow_share(const Eigen::MatrixX2d& series);

/// Contiguous blocks of the recording over which a wander is measured.
constexpr int kWanderBlocks = 20;

/// Whether `correction` (what a candidate changes, on rows in time order) stands out of the wander
/// `left` (what remains beside it): true when less than half of the correction's variance is slow,
/// or when the spread of its block means is at least twice that of what remains.
bool stands_out_of_wander(const Eigen::MatrixX2d& correction, const Eigen::MatrixX2d& left);

}  // namespace gc
