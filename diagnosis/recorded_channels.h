// The channels of a recording as series in time order, for the data-quality detectors
// (data_quality.h): the measured moments, the inputs, and the optional channels where every row
// has them.
#pragma once

#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "core/recorded_sample.h"

namespace gc {

struct RecordedChannel {
  std::string name;                ///< as docs/recordings.md names the quantity: "msy", "torque", ...
  std::string unit;                ///< SI
  std::vector<std::size_t> rows;   ///< indices into the recording, in time order
  std::vector<double> values;      ///< the channel's value on each of `rows`
  /// Measured by a sensor with noise (the moments, hub motion): identical neighbours are an
  /// artefact. The inputs may be set points that hold a value by design.
  bool measured = false;
};

/// Every channel with a value on every row, in time order.
std::vector<RecordedChannel> recorded_channels(std::span<const RecordedSample> observations);

/// `observations`' rows in time order (ties in the recording's order).
std::vector<std::size_t> rows_in_time_order(std::span<const RecordedSample> observations);

/// The channel changes from sample to sample as a noisy signal does: fewer than half of its
/// neighbours are identical. Where the inputs hold still (the same torque, misalignment and
/// direction on both rows, at least 20 such pairs), only those pairs count: a channel that stays
/// put while nothing drives it is noise-free, and its repeats are the physics'. Elsewhere a moment
/// channel's ties are counted without its longest run, the one a frozen bridge makes. An input must also
/// move roughly where it moves (its second differences at least a twentieth of its first): a smooth ramp
/// between holds is a programme, not a sensor's noise.
bool changes_every_sample(const RecordedChannel& channel, std::span<const RecordedSample> observations);

/// The channel's noise sigma from its successive differences, 1.4826 MAD / sqrt(2) (the mean
/// absolute difference times sqrt(pi) / 2 when ties make the MAD zero) [unit].
double difference_sigma(const std::vector<double>& values);

}  // namespace gc
