#include "diagnosis/time_stamps.h"

#include <algorithm>
#include <cmath>

#include "diagnosis/median.h"
#include "diagnosis/verdict_text.h"
#include "core/engineering_text.h"

namespace gc {
namespace {

double time_of(std::span<const RecordedSample> observations, std::size_t row) { return observations[row].input.time_s; }

}  // namespace

double sample_period(std::span<const RecordedSample> observations, const std::vector<std::size_t>& ordered) {
  std::vector<double> steps;
  for (std::size_t i = 1; i < ordered.size(); ++i) {
    const double dt = time_of(observations, ordered[i]) - time_of(observations, ordered[i - 1]);
    if (dt > 0.0) steps.push_back(dt);
  }
  return median(std::move(steps));
}

std::optional<DataQualityFinding> time_gaps(std::span<const RecordedSample> observations,
                                            const std::vector<std::size_t>& ordered, const DataQualitySettings& settings) {
  const double period = sample_period(observations, ordered);
  if (!(period > 0.0)) return std::nullopt;
  DataQualityFinding finding{DataQualityKind::time_gap, "time", {}, {}, false, ""};
  double longest = 0.0;
  for (std::size_t i = 1; i < ordered.size(); ++i) {
    const double dt = time_of(observations, ordered[i]) - time_of(observations, ordered[i - 1]);
    if (dt <= settings.gap_periods * period) continue;
    finding.rows.push_back(ordered[i]);
    longest = std::max(longest, dt);
  }
  if (finding.rows.empty()) return std::nullopt;
  std::sort(finding.rows.begin(), finding.rows.end());
  finding.detail = std::to_string(finding.rows.size()) + (finding.rows.size() == 1 ? " gap" : " gaps") +
                   " longer than " + short_number(settings.gap_periods) + " sample periods (period " +
                   engineering_text(period, "s") + ", longest gap " + engineering_text(longest, "s") +
                   ") before the rows listed: frames lost or logging paused; the noise's correlation does not carry "
                   "across a gap, and a rate (dzeta/dt) across it is an average; kept";
  return finding;
}

std::optional<DataQualityFinding> irregular_stamps(std::span<const RecordedSample> observations,
                                                   const std::vector<std::size_t>& ordered,
                                                   const DataQualitySettings& settings) {
  const double period = sample_period(observations, ordered);
  DataQualityFinding finding{DataQualityKind::irregular_time, "time", {}, {}, false, ""};
  std::size_t duplicates = 0, backwards = 0;
  for (std::size_t i = 1; i < observations.size(); ++i) {
    const double dt = time_of(observations, i) - time_of(observations, i - 1);
    if (dt > 0.0) continue;
    finding.rows.push_back(i);
    (dt == 0.0 ? duplicates : backwards) += 1;
  }
  std::vector<double> regular;
  for (std::size_t i = 1; i < ordered.size(); ++i) {
    const double dt = time_of(observations, ordered[i]) - time_of(observations, ordered[i - 1]);
    if (dt > 0.0 && dt <= settings.gap_periods * period) regular.push_back(dt);
  }
  const double centre = median(regular);
  for (double& dt : regular) dt = std::abs(dt - centre);
  const double jitter = period > 0.0 ? 1.4826 * median(std::move(regular)) / period : 0.0;
  std::string what;
  if (duplicates > 0) {
    what = std::to_string(duplicates) + " rows share their stamp with the row before (a rate such as dzeta/dt is "
           "undefined there, and the noise's correlation is counted per row, not per second)";
  }
  if (backwards > 0) {
    what += (what.empty() ? "" : "; ") + std::to_string(backwards) +
            " rows step back in time (the diagnosis reads the rows in time order)";
  }
  if (jitter > settings.jitter_share) {
    what += (what.empty() ? "" : "; ") + std::string("the period jitters by ") +
            std::to_string(static_cast<int>(std::lround(100.0 * jitter))) + " % (robust spread of the steps of " +
            engineering_text(period, "s") + "): the noise's lag-1 correlation is an average over uneven steps";
  }
  if (what.empty()) return std::nullopt;
  finding.detail = what + "; kept";
  return finding;
}

}  // namespace gc
