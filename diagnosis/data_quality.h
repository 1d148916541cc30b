// Data quality before physics (docs/diagnosis.md, "Data quality"): instrument artefacts found in
// the recording itself, each reported with its channel, rows and time span, so that a rail, a
// frozen channel or a dropout is never read as an effect and a refusal is never read as noise.
// Samples that did not measure the coupling (clipped, stuck, dropped to zero) are excluded from
// the physics; what changes only how the noise is read (quantisation, irregular time stamps,
// gaps) is reported and kept. Spikes need the model's residual and are found later
// (outlier_positions); a polarity flip is refused by the model and reported here with its advice.
#pragma once

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "core/recorded_sample.h"

namespace gc {

enum class DataQualityKind {
  clipped,         ///< samples at the channel's rail (its extreme value, piled up)
  stuck,           ///< a run of identical values far longer than quantisation explains
  dropout,         ///< a noisy channel reading exactly zero where its level is far from zero
  time_gap,        ///< a time step much longer than the sample period
  polarity_flip,   ///< the torque negative on some rows and positive on others
  quantisation,    ///< values on a grid coarse against the channel's noise
  irregular_time,  ///< time stamps duplicated or jittered
  spike,           ///< isolated samples far from their neighbours in the model's residual
  model_jump,      ///< rows where the model jumps within the input sensors' noise (model_jumps.h)
};

/// "clipped", "stuck", "dropout", "time_gap", "polarity_flip", "quantisation", "irregular_time", "spike",
/// "model_jump".
const char* to_string(DataQualityKind kind);

/// A contiguous stretch of rows (indices into the recording, in time order).
struct RowSpan {
  std::size_t first_row = 0;
  std::size_t last_row = 0;  ///< inclusive
  double t_start_s = 0.0;
  double t_end_s = 0.0;
};

struct DataQualityFinding {
  DataQualityKind kind = DataQualityKind::clipped;
  std::string channel;              ///< "msy", "msz", "torque", "time", ... (docs/recordings.md)
  std::vector<std::size_t> rows;    ///< the rows affected, ascending (empty for a whole-channel property)
  std::vector<RowSpan> spans;       ///< the rows as contiguous stretches
  bool excluded = false;            ///< the rows are left out of the physics
  std::string detail;               ///< plain language: what was seen, what it means, what to do
};

/// Rows left out of the diagnosis, as one stretch, and why.
struct ExcludedRange {
  RowSpan span;
  std::string reason;
};

struct DataQualitySettings {
  /// A run of identical values is stuck when a run that long would arise by chance (each
  /// neighbour equal with the channel's own tie rate) less than this often in the recording.
  double stuck_chance = 1e-3;
  std::size_t shortest_stuck_run = 5;   ///< samples; shorter runs are never called stuck
  /// A rail holds at least this many samples at the channel's extreme, and at least
  /// rail_pile_up times as many as the next value inward (a tail thins toward its extreme).
  std::size_t shortest_rail = 5;
  double rail_pile_up = 2.0;
  /// A zero is a dropout when the channel's level around it is this many noise deviations from zero.
  double dropout_deviations = 8.0;
  /// A time step this many sample periods long is a gap.
  double gap_periods = 5.0;
  /// Quantisation is reported when the step is at least this share of the channel's noise sigma
  /// (finer, rounding adds under 0.6 % to the noise variance and ties are rare).
  double coarse_step_share = 0.25;
  /// Time stamps are jittered when the robust spread of the steps exceeds this share of the period.
  double jitter_share = 0.01;
};

struct DataQuality {
  std::vector<DataQualityFinding> findings;
  std::vector<std::size_t> excluded_rows;  ///< ascending: the union of the excluded findings' rows
};

/// The artefacts of `observations` (any order; rows are indices into it).
DataQuality check_data_quality(std::span<const RecordedSample> observations, const DataQualitySettings& settings = {});

/// The rows `findings` exclude, ascending, without repeats (a negative torque's are the model's
/// refusals, counted as refused).
std::vector<std::size_t> excluded_rows_of(const std::vector<DataQualityFinding>& findings);

/// The spikes the model's residual shows (outlier_positions, `rows` into the recording), as a
/// finding: isolated samples far from their neighbours, a DAQ's spikes; nullopt for none.
std::optional<DataQualityFinding> spike_finding(std::vector<std::size_t> rows, std::span<const RecordedSample> observations,
                                                double deviations);

/// Every row left out, as stretches with one reason each: the excluded findings' kind and channel,
/// then the rows the model refused (`refused`, ascending) with `refusal` (the model's first reason).
std::vector<ExcludedRange> excluded_ranges(const std::vector<DataQualityFinding>& findings,
                                           const std::vector<std::size_t>& refused, const std::string& refusal,
                                           std::span<const RecordedSample> observations);

/// `rows` (ascending) as stretches of consecutive rows, with their times.
std::vector<RowSpan> row_spans(const std::vector<std::size_t>& rows, std::span<const RecordedSample> observations);

/// "Data quality: msy clipped: <detail>. torque polarity_flip: <detail>." (spikes aside: the
/// outliers' sentence counts them); empty when there is nothing to say.
std::string data_quality_text(const std::vector<DataQualityFinding>& findings);

/// "rows 120-180 (t = 1.2-1.8 s), 400 (t = 4 s)", at most `most` stretches, then "and N more".
std::string spans_text(const std::vector<RowSpan>& spans, std::size_t most = 3);

}  // namespace gc
