#include "diagnosis/model_jumps.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <sstream>

#include "diagnosis/input_shrinkage.h"
#include "diagnosis/median.h"
#include "diagnosis/row_selection.h"
#include "diagnosis/verdict_text.h"

namespace gc {
namespace {

/// The running medians of an input: over 4 s, several correlation times of a transducer's filter;
/// and shorter, which a programme's turns (a misalignment sweep reversing every few seconds) do not
/// reach. The smallest estimate is the noise's: a turn inside the window only adds to it.
constexpr double kMedianWindowsS[] = {0.25, 1.0, 4.0};
constexpr double kLeastWindowRows = 9.0;
constexpr std::size_t kLeastRows = 31;
constexpr double kNoiseDeviations = 2.0;   ///< how far either side of the logged input is tested
constexpr double kJumpShareOfNoise = 0.25;  ///< a second difference beyond this share of the moments' noise is a jump

/// The largest second difference of the two moment channels across +-step about `s`, along the
/// input `value` points at; 0 where the model refuses a side (beyond the jam angle, a negative
/// misalignment).
double second_difference(const CouplingModel& model, const MeasurementSample& s, double MeasurementSample::*input,
                         double step, const SensorMoments& centre) {
  MeasurementSample lo = s, hi = s;
  lo.*input -= step;
  hi.*input += step;
  if (lo.*input < 0.0) return 0.0;
  try {
    const SensorMoments a = model.predict(lo).moments, b = model.predict(hi).moments;
    return std::max(std::abs(a.y_nm - 2.0 * centre.y_nm + b.y_nm), std::abs(a.z_nm - 2.0 * centre.z_nm + b.z_nm));
  } catch (const std::exception&) {
    return 0.0;
  }
}

/// input_noise_sigma from the departures at `tested`.
double noise_at(std::span<const RecordedSample> observations, const std::vector<std::size_t>& rows,
                const std::vector<std::size_t>& tested, double (*value)(const MeasurementSample&)) {
  if (rows.size() < kLeastRows) return 0.0;
  const double interval = (observations[rows.back()].input.time_s - observations[rows.front()].input.time_s) /
                          static_cast<double>(rows.size() - 1);
  double sigma = std::numeric_limits<double>::infinity();
  for (const double window_s : kMedianWindowsS) {
    const std::vector<double> centre =
        centred_medians(observations, rows, std::max(window_s, kLeastWindowRows * interval), tested, value);
    std::vector<double> departures(tested.size());
    for (std::size_t j = 0; j < tested.size(); ++j) departures[j] = std::abs(value(observations[tested[j]].input) - centre[j]);
    sigma = std::min(sigma, 1.4826 * median(std::move(departures)));
  }
  return sigma;
}

}  // namespace

double input_noise_sigma(std::span<const RecordedSample> observations, const std::vector<std::size_t>& rows,
                         double (*value)(const MeasurementSample&)) {
  return noise_at(observations, rows, evenly_spaced(rows, kJumpTestedRows), value);
}

std::optional<DataQualityFinding> rows_at_model_jumps(const CouplingModel& model,
                                                      std::span<const RecordedSample> observations,
                                                      const std::vector<std::size_t>& rows, double moment_sigma_nm,
                                                      const ParallelFor& parallel) {
  const std::vector<std::size_t> tested = evenly_spaced(rows, kJumpTestedRows);
  // The two inputs' noises side by side: their running medians were a serial stretch of a diagnosis.
  constexpr std::array<double (*)(const MeasurementSample&), 2> kInputs{
      [](const MeasurementSample& s) { return s.torque_nm; }, [](const MeasurementSample& s) { return s.misalignment_rad; }};
  std::array<double, 2> sigma{};
  parallel(kInputs.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) sigma[k] = noise_at(observations, rows, tested, kInputs[k]);
  });
  const double torque_sigma = sigma[0], zeta_sigma = sigma[1];
  if (!(moment_sigma_nm > 0.0) || (torque_sigma <= 0.0 && zeta_sigma <= 0.0)) return std::nullopt;
  std::vector<char> jumps(tested.size(), 0);
  const double least = kJumpShareOfNoise * moment_sigma_nm;
  parallel(tested.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) {
      const MeasurementSample& s = observations[tested[k]].input;
      SensorMoments centre;
      try {
        centre = model.predict(s).moments;
      } catch (const std::exception&) {
        continue;
      }
      jumps[k] = (torque_sigma > 0.0 && second_difference(model, s, &MeasurementSample::torque_nm,
                                                          kNoiseDeviations * torque_sigma, centre) > least) ||
                 (zeta_sigma > 0.0 && second_difference(model, s, &MeasurementSample::misalignment_rad,
                                                        kNoiseDeviations * zeta_sigma, centre) > least);
    }
  });
  // Each row follows the tested row of its stretch (evenly_spaced takes position k n / count).
  std::vector<std::size_t> flagged;
  for (std::size_t p = 0; p < rows.size(); ++p) {
    if (jumps[std::min(tested.size() - 1, p * tested.size() / rows.size())]) flagged.push_back(rows[p]);
  }
  if (flagged.empty()) return std::nullopt;
  std::sort(flagged.begin(), flagged.end());
  // At most half the rows: beyond that the running median's departures are the programme's own
  // wander (a misalignment in an Ornstein-Uhlenbeck walk read as 0.2 mrad of probe noise put 11,401
  // of 11,421 rows within reach of a step), not a sensor's noise, and nothing is said.
  if (2 * flagged.size() > rows.size()) return std::nullopt;
  DataQualityFinding finding{DataQualityKind::model_jump, "torque, misalignment", flagged, row_spans(flagged, observations),
                             true, ""};
  std::ostringstream detail;
  detail << flagged.size() << " rows of " << rows.size() << " have an input within two deviations of its sensor's noise "
         << "(torque " << short_number(torque_sigma) << " N·m, misalignment " << short_number(zeta_sigma)
         << " rad) of a step of the model's moments (a pair of teeth more in contact, eqs 13 and 42-43): logged on "
         << "either side of the step at random, the model fed them jumps where the coupling does not, and leaves a bias "
         << "no effect explains; excluded";
  finding.detail = detail.str();
  return finding;
}

}  // namespace gc
