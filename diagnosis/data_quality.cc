#include "diagnosis/data_quality.h"

#include <algorithm>
#include <map>
#include <optional>

#include "diagnosis/dropouts.h"
#include "diagnosis/flat_values.h"
#include "diagnosis/polarity_flip.h"
#include "diagnosis/quantisation.h"
#include "diagnosis/recorded_channels.h"
#include "diagnosis/time_stamps.h"
#include "diagnosis/verdict_text.h"
#include "core/engineering_text.h"

namespace gc {
namespace {

void add(std::vector<DataQualityFinding>& findings, std::optional<DataQualityFinding> finding) {
  if (finding) findings.push_back(std::move(*finding));
}

/// A channel that stops measuring: dropped to zero, at its rail, or frozen; each sample claimed
/// once, in that order (a run of zeros or at the rail is also a run of identical values).
void channel_artefacts(const RecordedChannel& channel, const DataQualitySettings& settings,
                       std::vector<DataQualityFinding>& findings) {
  std::vector<std::size_t> taken;
  // A rail on the moment channels only: an input's top set point (a speed programme's 14 rpm held
  // for a few samples) piles up at its maximum as a rail does.
  const std::optional<DataQualityFinding> clipped =
      channel.measured ? clipped_samples(channel, settings) : std::nullopt;
  for (auto finding : {zero_dropouts(channel, settings), clipped}) {
    if (!finding) continue;
    taken.insert(taken.end(), finding->rows.begin(), finding->rows.end());
    findings.push_back(std::move(*finding));
  }
  std::sort(taken.begin(), taken.end());
  add(findings, stuck_runs(channel, positions_of(channel, taken), settings));
}

}  // namespace

const char* to_string(DataQualityKind kind) {
  switch (kind) {
    case DataQualityKind::clipped: return "clipped";
    case DataQualityKind::stuck: return "stuck";
    case DataQualityKind::dropout: return "dropout";
    case DataQualityKind::time_gap: return "time_gap";
    case DataQualityKind::polarity_flip: return "polarity_flip";
    case DataQualityKind::quantisation: return "quantisation";
    case DataQualityKind::irregular_time: return "irregular_time";
    case DataQualityKind::spike: return "spike";
    case DataQualityKind::model_jump: return "model_jump";
  }
  return "";
}

DataQuality check_data_quality(std::span<const RecordedSample> observations, const DataQualitySettings& settings) {
  DataQuality out;
  const std::vector<std::size_t> ordered = rows_in_time_order(observations);
  for (const RecordedChannel& channel : recorded_channels(observations)) {
    // A set point or a noise-free channel holds values by design: its repeats are no artefact.
    const bool noisy = changes_every_sample(channel, observations);
    if (noisy) channel_artefacts(channel, settings, out.findings);
    // A sensor's grid shows on a measured channel whatever its ties; an input on a coarse grid
    // cannot be told from set points, nor from a ramp that moves by the same step every sample (a
    // misalignment sweep of 98 µrad a sample read as an ADC step).
    if (channel.measured) add(out.findings, coarse_quantisation(channel, settings));
  }
  add(out.findings, negative_torque(observations, ordered));
  add(out.findings, time_gaps(observations, ordered, settings));
  add(out.findings, irregular_stamps(observations, ordered, settings));
  for (DataQualityFinding& finding : out.findings) {
    finding.spans = row_spans(finding.rows, observations);
    if (!finding.spans.empty()) finding.detail += ": " + spans_text(finding.spans);
  }
  out.excluded_rows = excluded_rows_of(out.findings);
  return out;
}

std::vector<std::size_t> excluded_rows_of(const std::vector<DataQualityFinding>& findings) {
  std::vector<std::size_t> rows;
  for (const DataQualityFinding& finding : findings) {
    // The model refuses a negative torque itself: those rows are counted as refused.
    if (finding.excluded && finding.kind != DataQualityKind::polarity_flip) {
      rows.insert(rows.end(), finding.rows.begin(), finding.rows.end());
    }
  }
  std::sort(rows.begin(), rows.end());
  rows.erase(std::unique(rows.begin(), rows.end()), rows.end());
  return rows;
}

std::optional<DataQualityFinding> spike_finding(std::vector<std::size_t> rows, std::span<const RecordedSample> observations,
                                                double deviations) {
  if (rows.empty()) return std::nullopt;
  std::sort(rows.begin(), rows.end());
  DataQualityFinding finding{DataQualityKind::spike, "msy, msz", rows, row_spans(rows, observations), true, ""};
  finding.detail = std::to_string(rows.size()) + " isolated samples more than " + short_number(deviations) +
                   " robust deviations from the running median of their neighbours in the model's residual: spikes "
                   "of the DAQ, not physics (a run of large residuals is kept as structure); excluded: " +
                   spans_text(finding.spans);
  return finding;
}

std::vector<ExcludedRange> excluded_ranges(const std::vector<DataQualityFinding>& findings,
                                           const std::vector<std::size_t>& refused, const std::string& refusal,
                                           std::span<const RecordedSample> observations) {
  std::map<std::size_t, std::string> reasons;
  for (const DataQualityFinding& f : findings) {
    if (!f.excluded) continue;
    const std::string reason = std::string(to_string(f.kind)) + " " + f.channel +
                               (f.kind == DataQualityKind::polarity_flip ? " (negative, refused by the model)" : "");
    for (std::size_t r : f.rows) reasons.emplace(r, reason);
  }
  for (std::size_t r : refused) reasons.emplace(r, "refused by the model (first: " + refusal + ")");
  std::vector<ExcludedRange> ranges;
  for (const auto& [row, reason] : reasons) {
    const double t = observations[row].input.time_s;
    if (!ranges.empty() && ranges.back().span.last_row + 1 == row && ranges.back().reason == reason) {
      ranges.back().span.last_row = row;
      ranges.back().span.t_end_s = t;
    } else {
      ranges.push_back({{row, row, t, t}, reason});
    }
  }
  return ranges;
}

std::vector<RowSpan> row_spans(const std::vector<std::size_t>& rows, std::span<const RecordedSample> observations) {
  std::vector<RowSpan> spans;
  for (std::size_t r : rows) {
    const double t = observations[r].input.time_s;
    if (!spans.empty() && spans.back().last_row + 1 == r) {
      spans.back().last_row = r;
      spans.back().t_end_s = t;
    } else {
      spans.push_back({r, r, t, t});
    }
  }
  return spans;
}

std::string data_quality_text(const std::vector<DataQualityFinding>& findings) {
  std::string text;
  for (const DataQualityFinding& f : findings) {
    if (f.kind == DataQualityKind::spike) continue;  // counted in the outliers' own sentence
    text += (text.empty() ? "Data quality: " : " ") + f.channel + " " + to_string(f.kind) + ": " + f.detail + ".";
  }
  return text;
}

std::string spans_text(const std::vector<RowSpan>& spans, std::size_t most) {
  std::string text;
  for (std::size_t k = 0; k < spans.size() && k < most; ++k) {
    const RowSpan& s = spans[k];
    text += (text.empty() ? "" : ", ");
    text += s.first_row == s.last_row
                ? std::to_string(s.first_row) + " (t = " + engineering_text(s.t_start_s, "s") + ")"
                : std::to_string(s.first_row) + "-" + std::to_string(s.last_row) + " (t = " +
                      engineering_range(s.t_start_s, s.t_end_s, "s") + ")";
  }
  if (spans.size() > most) text += " and " + std::to_string(spans.size() - most) + " more";
  return (spans.size() == 1 && spans.front().first_row == spans.front().last_row ? "row " : "rows ") + text;
}

}  // namespace gc
