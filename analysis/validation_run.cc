#include "analysis/validation_run.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "core/model_error.h"
#include "parallel/chunked_parallel_for.h"

namespace gc::analysis {
namespace {

struct Outcome {
  std::optional<SensorMoments> moments;
  std::string field;      // set when the model refused the sample
  std::string message;
};

void predict_range(const CouplingModel& model, const std::vector<RecordedSample>& samples,
                   std::size_t begin, std::size_t end, std::vector<Outcome>& outcomes) {
  for (std::size_t i = begin; i < end; ++i) {
    Outcome& outcome = outcomes[i];
    try {
      outcome.moments = model.predict_at(std::span<const RecordedSample>(samples), i).moments;
    } catch (const InvalidInput& error) {
      outcome = {std::nullopt, error.field(), error.what()};
    } catch (const ModelError& error) {
      outcome = {std::nullopt, "model", error.what()};
    }
  }
}

// Each thread predicts one contiguous slice; outcomes keep the file order.
void predict_chunk(const CouplingModel& model, const std::vector<RecordedSample>& samples,
                   const ParallelFor& parallel_for, std::vector<Outcome>& outcomes) {
  outcomes.assign(samples.size(), Outcome{});
  parallel_for(samples.size(), [&](std::size_t begin, std::size_t end) {
    predict_range(model, samples, begin, end, outcomes);
  });
}

// One part of a model's statistics (ValidationAccumulator::add_part; the last: rejections, the
// plot points and the scale) fed the chunk in file order.
void accumulate_part(std::size_t part, const std::vector<RecordedSample>& samples,
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
void accumulate(const std::vector<RecordedSample>& samples, const std::vector<Outcome>& outcomes,
                const ParallelFor& parallel_for, ModelRun& run) {
  parallel_for(ValidationAccumulator::kParts + 1, [&](std::size_t begin, std::size_t end) {
    for (std::size_t part = begin; part < end; ++part) accumulate_part(part, samples, outcomes, run);
  });
}

}  // namespace

RecordingSummary run_validation(const std::filesystem::path& path, std::vector<ModelRun>& runs,
                                const ValidationRunOptions& options) {
  const unsigned threads = static_cast<unsigned>(std::max(1, options.threads));
  RecordingReader reader(path, RecordingOptions{{}, options.renames, options.negated,
                                                options.source_name, threads});
  const ParallelFor parallel_for = chunked_parallel_for(threads);
  std::vector<RecordedSample> chunk;
  std::vector<Outcome> outcomes;
  double largest_misalignment_rad = 0.0, largest_torque_nm = 0.0;
  while (reader.next_chunk(chunk, options.chunk_samples)) {
    for (const RecordedSample& sample : chunk) {
      largest_misalignment_rad = std::max(largest_misalignment_rad, std::abs(sample.input.misalignment_rad));
      largest_torque_nm = std::max(largest_torque_nm, std::abs(sample.input.torque_nm));
    }
    for (ModelRun& run : runs) {
      predict_chunk(*run.model, chunk, parallel_for, outcomes);
      accumulate(chunk, outcomes, parallel_for, run);
    }
  }
  return {options.source_name.empty() ? path.filename().string() : options.source_name,
          reader.rows_read(), reader.excluded_rows(), reader.problems(),
          reader.ignored_columns(), largest_misalignment_rad, largest_torque_nm};
}

}  // namespace gc::analysis
