// The rows a diagnosis works on, as indices into the recording: all of them in time order, a few
// evenly spaced through them (the search rows, the refit rows), and a residual's rows picked out
// for a subset of them.
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include <Eigen/Dense>

#include "core/recorded_sample.h"

namespace gc {

/// Every row of `observations`, in time order (stable: rows of one time keep their order).
std::vector<std::size_t> time_ordered(std::span<const RecordedSample> observations);

/// At most `count` rows evenly spaced through `rows` (which are in time order).
std::vector<std::size_t> evenly_spaced(const std::vector<std::size_t>& rows, std::size_t count);

/// The rows at `positions` of `rows` (a fold's positions into the search rows, as recording rows).
std::vector<std::size_t> rows_at(std::span<const std::size_t> rows, const std::vector<std::size_t>& positions);

/// The rows of `residual` (one per row of `all`) that `subset` names; `subset` in the order of `all`.
Eigen::MatrixX2d select_rows(const Eigen::MatrixX2d& residual, const std::vector<std::size_t>& all,
                             const std::vector<std::size_t>& subset);

}  // namespace gc
