// An input that holds one value for a stretch is either frozen (its sensor stopped while the
// coupling went on) or held by the test programme (a staircase of torque at one misalignment, a
// misalignment held while the direction turns). The input alone cannot tell them apart when the
// programme moves it roughly elsewhere (an Ornstein-Uhlenbeck load, noise-free). The moments can:
// fed the held value, the model predicts the moments in the stretch as well as elsewhere when the
// input did hold, and worse when the coupling moved on. A held stretch is then kept for the physics,
// not cut out: each cut leaves a gap in time that a slow noise wanders across, which the surrogates
// of the claim rule, drawn on the rows as if they were evenly spaced, do not reproduce (a formula of
// constants and temperature was claimed in a wandering zero across the gap a held misalignment left,
// zoo seed 20261225 draw 108; a held torque left 334 of 1222 rows, draw 425).
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include "core/recorded_sample.h"
#include "diagnosis/data_quality.h"
#include "diagnosis/model_residuals.h"

namespace gc {

/// True when `quality` has an excluded `stuck` finding on an input: what release_programme_holds judges.
bool has_held_inputs(const DataQuality& quality);

/// Gives back to the physics each run of an input's `stuck` finding in `quality` whose residual
/// mean square (both channels, rows the model predicts) is at most `most_ratio` times that of the
/// rows no finding excludes; `residuals` holds one row per `rows` (any order). A finding left with
/// no run is removed; one left with some says how many runs were a programme's hold.
/// quality.excluded_rows is updated. Moment channels are not judged: a frozen bridge is frozen.
void release_programme_holds(DataQuality& quality, std::span<const RecordedSample> observations,
                             std::span<const std::size_t> rows, const ModelResiduals& residuals,
                             double most_ratio = 1.5);

}  // namespace gc
