#include "diagnosis/polarity_flip.h"

#include <algorithm>
#include <string>

#include "core/engineering_text.h"

namespace gc {

std::optional<DataQualityFinding> negative_torque(std::span<const RecordedSample> observations,
                                                  const std::vector<std::size_t>& ordered) {
  DataQualityFinding finding{DataQualityKind::polarity_flip, "torque", {}, {}, true, ""};
  std::optional<double> first_negative;
  for (std::size_t r : ordered) {
    if (!(observations[r].input.torque_nm < 0.0)) continue;
    finding.rows.push_back(r);
    if (!first_negative) first_negative = observations[r].input.time_s;
  }
  if (finding.rows.empty()) return std::nullopt;
  std::sort(finding.rows.begin(), finding.rows.end());
  const std::string count = std::to_string(finding.rows.size()) + " of " + std::to_string(observations.size()) + " rows";
  if (finding.rows.size() == observations.size()) {
    finding.detail = "the torque is negative on all " + std::to_string(finding.rows.size()) +
                     " rows, as a dyno that logs the drive torque negative writes it; --negate torque reads it (the "
                     "model takes the torque as a magnitude, T > 0); refused by the model";
    return finding;
  }
  finding.detail = "the torque is negative on " + std::to_string(finding.rows.size()) + " of " +
                   std::to_string(observations.size()) + " rows, from t = " + engineering_text(*first_negative, "s") +
                   ": its sign turns partway (a channel's polarity swapped). The model takes the torque as a "
                   "magnitude (T > 0); --negate torque reads a torque logged negative, so split the recording where "
                   "the sign turns and read the negative part with --negate torque; refused by the model";
  return finding;
}

namespace {

constexpr std::size_t kFewestFlipped = 10;  ///< rows: fewer cannot tell a flip from a burst
constexpr double kFlipFit = 0.25;           ///< the negative leaves under this share of the model's misfit

double measured(const RecordedSample& s, int channel) { return channel == 0 ? s.measured.y_nm : s.measured.z_nm; }

/// The first row of the flipped tail of one channel, or nullopt.
std::optional<std::size_t> flip_start(std::span<const RecordedSample> observations, const std::vector<std::size_t>& rows,
                                      const Eigen::MatrixX2d& residual, int channel) {
  const std::size_t n = rows.size();
  if (n < kFewestFlipped) return std::nullopt;
  // Tail sums from each split: the model's misfit, the negative's misfit, the model's moment.
  std::vector<double> same(n + 1, 0.0), flipped(n + 1, 0.0), signal(n + 1, 0.0);
  for (std::size_t i = n; i-- > 0;) {
    const double m = measured(observations[rows[i]], channel);
    const double p = m - residual(static_cast<Eigen::Index>(i), channel);
    same[i] = same[i + 1] + (m - p) * (m - p);
    flipped[i] = flipped[i + 1] + (m + p) * (m + p);
    signal[i] = signal[i + 1] + p * p;
  }
  std::optional<std::size_t> best;
  double best_gain = 0.0;
  for (std::size_t k = 0; k + kFewestFlipped <= n; ++k) {
    const double gain = same[k] - flipped[k];
    if (gain > best_gain) { best_gain = gain; best = k; }
  }
  if (!best) return std::nullopt;
  const std::size_t k = *best;
  if (flipped[k] >= kFlipFit * same[k] || signal[k] <= 2.0 * flipped[k]) return std::nullopt;
  return k;
}

}  // namespace

std::vector<DataQualityFinding> moment_polarity_flips(std::span<const RecordedSample> observations,
                                                      const std::vector<std::size_t>& rows,
                                                      const Eigen::MatrixX2d& residual) {
  std::vector<DataQualityFinding> findings;
  for (int channel = 0; channel < 2; ++channel) {
    const std::optional<std::size_t> k = flip_start(observations, rows, residual, channel);
    if (!k) continue;
    const std::string name = channel == 0 ? "msy" : "msz";
    DataQualityFinding finding{DataQualityKind::polarity_flip, name, {rows.begin() + static_cast<std::ptrdiff_t>(*k), rows.end()}, {}, true, ""};
    std::sort(finding.rows.begin(), finding.rows.end());
    const std::string count = std::to_string(finding.rows.size()) + " of " + std::to_string(rows.size()) + " rows";
    finding.detail = *k == 0
        ? "the measured " + name + " is the model's with the opposite sign on all " + std::to_string(rows.size()) +
              " rows: a bridge wired the other way round; --negate " + name + " reads it; excluded"
        : "the measured " + name + " turns to the model's with the opposite sign on " + count + ", from t = " +
              engineering_text(observations[rows[*k]].input.time_s, "s") +
              " (a swapped bridge lead); split the recording there and read the rest with --negate " + name + "; excluded";
    finding.spans = row_spans(finding.rows, observations);
    finding.detail += ": " + spans_text(finding.spans);
    findings.push_back(std::move(finding));
  }
  return findings;
}

}  // namespace gc
