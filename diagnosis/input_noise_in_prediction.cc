#include "diagnosis/input_noise_in_prediction.h"

#include <array>
#include <exception>
#include <optional>
#include <vector>

#include "diagnosis/median.h"
#include "diagnosis/model_jumps.h"
#include "diagnosis/row_selection.h"

namespace gc {
namespace {

constexpr std::size_t kRowsProbed = 64;

/// An input the model reads: its value, and the sample with it moved by `by`; absent where not
/// recorded.
struct Input {
  double (*value)(const MeasurementSample&);
  std::optional<MeasurementSample> (*moved)(const MeasurementSample&, double by);
};

template <double MeasurementSample::*field>
Input always() {
  return {[](const MeasurementSample& s) { return s.*field; },
          [](const MeasurementSample& s, double by) -> std::optional<MeasurementSample> {
            MeasurementSample out = s;
            out.*field += by;
            return out;
          }};
}

template <std::optional<double> MeasurementSample::*field>
Input where_recorded() {
  return {[](const MeasurementSample& s) { return (s.*field).value_or(0.0); },
          [](const MeasurementSample& s, double by) -> std::optional<MeasurementSample> {
            if (!(s.*field)) return std::nullopt;
            MeasurementSample out = s;
            out.*field = *(s.*field) + by;
            return out;
          }};
}

}  // namespace

Eigen::Array2d input_noise_in_prediction(const CouplingModel& model, std::span<const RecordedSample> observations,
                                         std::span<const std::size_t> rows) {
  const std::array<Input, 5> inputs{always<&MeasurementSample::torque_nm>(), always<&MeasurementSample::misalignment_rad>(),
                                    always<&MeasurementSample::direction_rad>(),
                                    where_recorded<&MeasurementSample::speed_rpm>(),
                                    where_recorded<&MeasurementSample::temperature_c>()};
  const std::vector<std::size_t> all(rows.begin(), rows.end());
  const std::vector<std::size_t> probed = evenly_spaced(all, kRowsProbed);
  Eigen::Array2d variance = Eigen::Array2d::Zero();
  for (const Input& input : inputs) {
    const double sigma = input_noise_sigma(observations, all, input.value);
    if (!(sigma > 0.0)) continue;
    std::array<std::vector<double>, 2> squares;
    for (const std::size_t row : probed) {
      const MeasurementSample& s = observations[row].input;
      const std::optional<MeasurementSample> lo = input.moved(s, -sigma), hi = input.moved(s, sigma);
      if (!lo || !hi) continue;
      try {
        const SensorMoments a = model.predict(*lo).moments, b = model.predict(*hi).moments;
        squares[0].push_back(0.25 * (b.y_nm - a.y_nm) * (b.y_nm - a.y_nm));
        squares[1].push_back(0.25 * (b.z_nm - a.z_nm) * (b.z_nm - a.z_nm));
      } catch (const std::exception&) {
        // A side the model refuses (beyond the jam angle, a negative misalignment) says nothing.
      }
    }
    for (int c = 0; c < 2; ++c) variance(c) += median(std::move(squares[static_cast<std::size_t>(c)]));
  }
  return variance.sqrt();
}

}  // namespace gc
