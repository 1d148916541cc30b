#include "analysis/validation_run.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <future>
#include <limits>
#include <numeric>
#include <optional>
#include <span>

#include <fmt/format.h>

#include "core/model_error.h"
#include "parallel/chunked_parallel_for.h"

namespace gc::analysis {
namespace {

struct Outcome {
  std::optional<SensorMoments> moments;
  std::string field;      // set when the model refused the sample
  std::string message;
};

// Samples [begin, end) of `samples`, each predicted from all of `samples` (as predict_at, the
// slice at once: CouplingModel::moments_at), into outcomes[0, end - begin).
void predict_range(const CouplingModel& model, std::span<const RecordedSample> samples,
                   std::size_t begin, std::size_t end, std::size_t first, std::vector<Outcome>& outcomes) {
  std::vector<std::size_t> rows(end - begin);
  std::iota(rows.begin(), rows.end(), begin);
  const CouplingModel::MomentsAtRows m = model.moments_at(samples, rows);
  for (std::size_t k = 0; k < rows.size(); ++k) {
    Outcome& outcome = outcomes[rows[k] - first];
    if (m.errors[k].empty()) {
      outcome.moments = m.moments[k];
    } else {
      outcome = {std::nullopt, m.fields[k].empty() ? "model" : m.fields[k], m.errors[k]};
    }
  }
}

// Each thread predicts one contiguous slice of [begin, end); outcomes keep the file order.
void predict_rows(const CouplingModel& model, std::span<const RecordedSample> samples, std::size_t begin,
                  std::size_t end, const ParallelFor& parallel_for, std::vector<Outcome>& outcomes) {
  outcomes.assign(end - begin, Outcome{});
  parallel_for(end - begin, [&](std::size_t b, std::size_t e) {
    predict_range(model, samples, begin + b, begin + e, begin, outcomes);
  });
}

// One part of a model's statistics (ValidationAccumulator::add_part; the last: rejections, the
// plot points and the scale) fed the rows predicted in file order.
void accumulate_part(std::size_t part, std::span<const RecordedSample> samples,
                     const std::vector<Outcome>& outcomes, ModelRun& run) {
  const bool validation_part = part < ValidationAccumulator::kParts;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const Outcome& outcome = outcomes[i];
    if (validation_part) {
      if (outcome.moments) run.validation.add_part(part, samples[i], *outcome.moments);
    } else {
      if (outcome.moments) {
        run.scale.add(samples[i].measured, *outcome.moments);
      } else {
        run.validation.reject(samples[i], outcome.field, outcome.message);
      }
      run.points.add(samples[i], outcome.moments);
    }
  }
}

// The statistics were a fifth of validate's work on one thread: their parts run on several,
// each in file order, so the result keeps its bits whatever the thread count.
void accumulate(std::span<const RecordedSample> samples, const std::vector<Outcome>& outcomes,
                const ParallelFor& parallel_for, ModelRun& run) {
  parallel_for(ValidationAccumulator::kParts + 1, [&](std::size_t begin, std::size_t end) {
    for (std::size_t part = begin; part < end; ++part) accumulate_part(part, samples, outcomes, run);
  });
}

// Rows [begin, end) of `samples` through every model, in file order.
void validate_rows(std::span<const RecordedSample> samples, std::size_t begin, std::size_t end,
                   const ParallelFor& parallel_for, std::vector<ModelRun>& runs, std::vector<Outcome>& outcomes) {
  if (begin == end) return;
  for (ModelRun& run : runs) {
    predict_rows(*run.model, samples, begin, end, parallel_for, outcomes);
    accumulate(samples.subspan(begin, end - begin), outcomes, parallel_for, run);
  }
}

// A time's rounding slack: t - delay - average computed another way may differ in its last bits.
double slack_s(double time_s) { return 1e-9 * std::max(1.0, std::abs(time_s)); }

// The chunks of a recording with what the models read of the rows around them. An effect that
// reads other samples than the one predicted (CouplingModel::input_reach: moment_delay's delay and
// average, a formula's ringing mode) sees at a chunk's first rows the rows before it and, for a
// negative delay, at its last rows the rows after it; predicted from the chunk alone those rows
// were predicted as if the recording started (or ended) there, so validate's numbers depended on
// where the chunks of 32,768 samples fell. The window holds the rows still needed before, the rows
// predicted once the rows they read after have been read, and the chunk read last.
class RecordingWindow {
 public:
  explicit RecordingWindow(const std::vector<ModelRun>& runs) : runs_(runs) {}

  /// Drops the rows no longer needed (those before what the rows not yet predicted, `chunk`'s
  /// among them, read), then appends `chunk`. Throws InvalidInput when a row reads further back
  /// than the rows kept: its reach is longer than the chunk before and what that chunk's rows
  /// read (a moment_delay average at a speed that fell tenfold within a chunk).
  void add(const std::vector<RecordedSample>& chunk) {
    for (const RecordedSample& sample : chunk) reach_.push_back(reach(sample.input));
    // The earliest time a row not yet predicted reads, and that row.
    double needed_from_s = std::numeric_limits<double>::infinity();
    const MeasurementSample* needing = nullptr;
    for (std::size_t i = next_; i < reach_.size(); ++i) {
      const MeasurementSample& input = i < samples_.size() ? samples_[i].input : chunk[i - samples_.size()].input;
      if (input.time_s - reach_[i].before_s < needed_from_s) {
        needed_from_s = input.time_s - reach_[i].before_s;
        needing = &input;
      }
    }
    // Kept: the last row before the stretch needed, and all after it.
    std::size_t keep = next_;
    while (needing != nullptr && keep > 0 &&
           samples_[keep - 1].input.time_s >= needed_from_s - slack_s(needed_from_s)) {
      --keep;
    }
    if (needing != nullptr && keep == 0 && !samples_.empty() && !from_start_) {
      throw InvalidInput("recording", fmt::format(
          "the model reads the inputs from {:g} s on for the sample at {:g} s ({:g} s before it: input "
          "timing or history), further back than validate still holds (from {:g} s, what the rows before "
          "read): validate cannot predict it as in one pass", needed_from_s, needing->time_s,
          needing->time_s - needed_from_s, samples_.front().input.time_s));
    }
    if (keep > 0) --keep;
    samples_.erase(samples_.begin(), samples_.begin() + static_cast<std::ptrdiff_t>(keep));
    reach_.erase(reach_.begin(), reach_.begin() + static_cast<std::ptrdiff_t>(keep));
    next_ -= keep;
    from_start_ = from_start_ && keep == 0;
    samples_.insert(samples_.end(), chunk.begin(), chunk.end());
  }

  /// The end of the rows that can be predicted now: all of them at the recording's end, else
  /// those whose reach after them ends before the last row read.
  std::size_t ready_end(bool at_end) const {
    if (at_end || samples_.empty()) return samples_.size();
    const double last_s = samples_.back().input.time_s;
    std::size_t end = next_;
    while (end < samples_.size()) {
      const double until_s = samples_[end].input.time_s + reach_[end].after_s;
      if (until_s + slack_s(until_s) >= last_s) break;
      ++end;
    }
    return end;
  }

  std::span<const RecordedSample> samples() const { return samples_; }
  std::size_t next() const { return next_; }
  void predicted_until(std::size_t end) { next_ = end; }

 private:
  InputReach reach(const MeasurementSample& sample) const {
    InputReach widest;
    for (const ModelRun& run : runs_) {
      const InputReach r = run.model->input_reach(sample);
      widest.before_s = std::max(widest.before_s, r.before_s);
      widest.after_s = std::max(widest.after_s, r.after_s);
    }
    return widest;
  }

  const std::vector<ModelRun>& runs_;
  std::vector<RecordedSample> samples_;
  std::vector<InputReach> reach_;   // of each of samples_
  std::size_t next_ = 0;            // the first row not yet predicted
  bool from_start_ = true;          // samples_ begins with the recording's first row
};

// The reader's next chunk, read on a thread of its own while the caller validates the current one
// (with more than one thread). Reading (the lines split, time and derived inputs in row order)
// ran on the calling thread alone between chunks: with 2 threads, the calling thread did two
// thirds of validate's work and the others waited.
class ChunkAhead {
 public:
  ChunkAhead(RecordingReader& reader, std::size_t chunk_samples, bool ahead)
      : reader_(reader), chunk_samples_(chunk_samples), ahead_(ahead) {
    if (ahead_) start();
  }
  ChunkAhead(const ChunkAhead&) = delete;
  ChunkAhead& operator=(const ChunkAhead&) = delete;

  /// Makes the next chunk current() and starts reading the one after; as next_chunk().
  bool next() {
    if (!ahead_) return reader_.next_chunk(current_, chunk_samples_);
    const bool more = reading_.get();  // rethrows the reader's InvalidInput
    current_.swap(read_);
    if (more) start();
    return more;
  }
  const std::vector<RecordedSample>& current() const { return current_; }

 private:
  void start() {
    reading_ = std::async(std::launch::async, [this] { return reader_.next_chunk(read_, chunk_samples_); });
  }

  RecordingReader& reader_;
  std::size_t chunk_samples_;
  bool ahead_;
  std::vector<RecordedSample> current_, read_;
  std::future<bool> reading_;  // declared last: destroyed first, waiting for a read under way
};

}  // namespace

RecordingSummary run_validation(const std::filesystem::path& path, std::vector<ModelRun>& runs,
                                const ValidationRunOptions& options) {
  const unsigned threads = static_cast<unsigned>(std::max(1, options.threads));
  RecordingReader reader(path, RecordingOptions{{}, options.renames, options.negated,
                                                options.source_name, threads});
  const ParallelFor parallel_for = chunked_parallel_for(threads);
  ChunkAhead chunks(reader, options.chunk_samples, threads > 1);
  std::vector<Outcome> outcomes;
  double largest_misalignment_rad = 0.0, largest_torque_nm = 0.0;
  const bool reads_other_samples = std::any_of(runs.begin(), runs.end(), [](const ModelRun& run) {
    return run.model->reads_other_samples();
  });
  RecordingWindow window(runs);
  bool more = true;
  while (more) {
    more = chunks.next();
    const std::vector<RecordedSample>& chunk = chunks.current();
    for (const RecordedSample& sample : chunk) {
      largest_misalignment_rad = std::max(largest_misalignment_rad, std::abs(sample.input.misalignment_rad));
      largest_torque_nm = std::max(largest_torque_nm, std::abs(sample.input.torque_nm));
    }
    if (!reads_other_samples) {  // each sample alone: the chunk is all a prediction reads
      validate_rows(chunk, 0, chunk.size(), parallel_for, runs, outcomes);
      continue;
    }
    window.add(chunk);
    const std::size_t end = window.ready_end(!more);
    validate_rows(window.samples(), window.next(), end, parallel_for, runs, outcomes);
    window.predicted_until(end);
  }
  return {options.source_name.empty() ? path.filename().string() : options.source_name,
          reader.rows_read(), reader.excluded_rows(), reader.problems(),
          reader.ignored_columns(), largest_misalignment_rad, largest_torque_nm};
}

}  // namespace gc::analysis
