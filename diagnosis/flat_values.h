// Two artefacts of a channel that stops measuring: a rail (the amplifier or ADC at its limit, the
// samples piled up at the channel's extreme value) and a stuck channel (a frozen reading: a run of
// identical values far longer than the channel's ties explain). Both are looked for only on a
// channel that changes from sample to sample (recorded_channels.h, changes_every_sample).
#pragma once

#include <optional>
#include <vector>

#include "diagnosis/data_quality.h"
#include "diagnosis/recorded_channels.h"

namespace gc {

/// The samples at the channel's maximum or minimum when at least settings.shortest_rail sit there
/// and rail_pile_up times as many as at the next value inward: a tail thins toward its extreme,
/// a rail piles samples up at it.
std::optional<DataQualityFinding> clipped_samples(const RecordedChannel& channel, const DataQualitySettings& settings);

/// Runs of identical values (positions not `taken`) that would arise by chance less than
/// settings.stuck_chance times in the channel, each neighbour tying with the channel's own tie rate
/// p (quantisation): n p^(L-1) < stuck_chance, and at least settings.shortest_stuck_run long.
std::optional<DataQualityFinding> stuck_runs(const RecordedChannel& channel, const std::vector<bool>& taken,
                                             const DataQualitySettings& settings);

/// Positions into `channel.values` (its time order) of `rows`, for marking them taken.
std::vector<bool> positions_of(const RecordedChannel& channel, const std::vector<std::size_t>& rows);

}  // namespace gc
