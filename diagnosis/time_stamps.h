// Time stamps as a DAQ writes them: gaps (a time step many sample periods long: frames lost or the
// logging paused), duplicates (two rows with one stamp), steps backwards, and jitter (an uneven
// period). Reported, never excluded: each row still measured the coupling, but the noise's
// correlation is per row, and a gap breaks it.
#pragma once

#include <optional>
#include <span>
#include <vector>

#include "diagnosis/data_quality.h"

namespace gc {

/// The recording's sample period: the median of its positive time steps [s] (0 with none).
double sample_period(std::span<const RecordedSample> observations, const std::vector<std::size_t>& ordered);

/// Time steps longer than settings.gap_periods sample periods: rows are those after each gap.
std::optional<DataQualityFinding> time_gaps(std::span<const RecordedSample> observations,
                                            const std::vector<std::size_t>& ordered, const DataQualitySettings& settings);

/// Duplicated stamps and steps backwards (in the recording's order), and a robust spread
/// (1.4826 MAD) of the regular steps above settings.jitter_share of the period.
std::optional<DataQualityFinding> irregular_stamps(std::span<const RecordedSample> observations,
                                                   const std::vector<std::size_t>& ordered,
                                                   const DataQualitySettings& settings);

}  // namespace gc
