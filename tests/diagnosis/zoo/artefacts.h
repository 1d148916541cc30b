// Instrument artefacts put on a clean recording, with the ground truth of where they are: for a
// data-quality stage to be tested against. Each generator draws its parameters from `rng`, changes
// `rec` (and, for empty cells, `empty`) and returns one truth per span it made. Rows are 0-based
// data rows (the CSV's line is row + 2). Channels are named as docs/recordings.md names the
// quantities: time, torque, misalignment, direction, speed, temperature, msy, msz.
#pragma once

#include <cstddef>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "tests/diagnosis/zoo/channels.h"
#include "tests/diagnosis/zoo/csv.h"
#include "tests/diagnosis/zoo/rng.h"

namespace gc::zoo {

struct ArtefactTruth {
  std::size_t rows = 0;       ///< rows of the recording
  std::string channel;        ///< "msy", "torque", "time", ...
  std::string kind;           ///< see the generators below
  std::size_t first_row = 0;  ///< first row affected (inclusive)
  std::size_t last_row = 0;   ///< last row affected (inclusive)
  std::string detail;         ///< the drawn parameters, as text
};

/// A recording with artefacts, ready to write (write_csv(rec, style, empty)).
struct ArtefactRecording {
  Channels rec;
  std::set<std::pair<std::size_t, int>> empty;  ///< (row, column) cells written empty
  std::vector<ArtefactTruth> truths;
};

// Each generator acts on one channel (Column) where that makes sense.
/// "clipped": the channel saturates at a rail set at 60-90 % of its range from its middle (upper
/// or lower rail); one truth per run of clipped rows.
std::vector<ArtefactTruth> clip_at_rail(Channels& rec, int column, Rng& rng);
/// "stuck": the channel holds its value for 20-2000 rows (at most a tenth of the record).
std::vector<ArtefactTruth> stuck_value(Channels& rec, int column, Rng& rng);
/// "dropout_empty" (cells left empty), "dropout_nan" ("nan" written) or "dropout_zero" (0 written):
/// a span of 1-200 rows of one channel.
std::vector<ArtefactTruth> dropout(Channels& rec, std::set<std::pair<std::size_t, int>>& empty, int column, Rng& rng);
/// "time_gap": the clock jumps ahead by 5-500 periods at one row (first = last = the row after the gap).
std::vector<ArtefactTruth> time_gap(Channels& rec, Rng& rng);
/// "polarity_flip": the channel's sign flips from a row to the end (a swapped bridge lead).
std::vector<ArtefactTruth> polarity_flip(Channels& rec, int column, Rng& rng);
/// "coarse_quantisation": the channel rounded to a step of 2-10 % of its range, whole record.
std::vector<ArtefactTruth> coarse_quantisation(Channels& rec, int column, Rng& rng);
/// "stamp_jitter" (whole record, 5-40 % of the period, kept non-decreasing), "duplicate_stamp"
/// (row i carries row i-1's stamp; one truth per row) and "backwards_stamp" (one row stamped
/// 0.5-3 periods before its predecessor).
std::vector<ArtefactTruth> stamp_jitter_artefact(Channels& rec, Rng& rng);
std::vector<ArtefactTruth> duplicate_stamps(Channels& rec, Rng& rng);
std::vector<ArtefactTruth> backwards_stamp(Channels& rec, Rng& rng);
/// "spike": isolated one-row spikes (3-20 of them, 10-40 times the channel's sample-to-sample
/// noise, at least 3 % of its range); "large_run": a run of 5-60 consecutive rows offset by as much.
std::vector<ArtefactTruth> isolated_spikes_artefact(Channels& rec, int column, Rng& rng);
std::vector<ArtefactTruth> large_run(Channels& rec, int column, Rng& rng);
/// "ringing": a lightly damped resonance of both moment channels (natural frequency 0.05-0.25 of
/// the sample rate, damping ratio 0.01-0.1) after each torque step of more than 5 % of the torque
/// span between two rows; amplitude 5-30 % of the step's moment change. One truth per step and
/// channel, to the row where the envelope falls below 2 % of its start.
std::vector<ArtefactTruth> ringing_after_torque_steps(Channels& rec, Rng& rng);

/// Every kind a generator above can return.
const std::vector<std::string>& artefact_kinds();

/// One artefact of `kind` (a name of artefact_kinds(), or its generator's: "dropout" draws one of
/// its three) on a channel drawn from those the kind suits, seeded.
ArtefactRecording apply_artefact(const Channels& clean, const std::string& kind, std::uint64_t seed);

}  // namespace gc::zoo
