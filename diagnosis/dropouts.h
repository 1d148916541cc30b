// A dropout: a channel that reads exactly zero for a sample or a few (a DAQ that writes 0 for a
// lost frame) while its level around them is far from zero. Empty and NaN cells never reach the
// diagnosis (the reader excludes their rows and `validate` lists them).
#pragma once

#include <optional>

#include "diagnosis/data_quality.h"
#include "diagnosis/recorded_channels.h"

namespace gc {

/// Runs of exact zeros whose neighbours (up to 5 non-zero values either side) have a median more
/// than settings.dropout_deviations of the channel's noise (difference_sigma) from zero.
std::optional<DataQualityFinding> zero_dropouts(const RecordedChannel& channel, const DataQualitySettings& settings);

}  // namespace gc
