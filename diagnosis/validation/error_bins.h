// Where the model fails: model errors binned by each input (torque, misalignment amplitude and
// direction, loading direction, time) and on a torque x misalignment map, in constant memory.
// Two models' binnings built with the same options have the same bins, so they can be shown
// side by side (before and after adding an effect).
#pragma once

#include <array>
#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/recorded_sample.h"
#include "diagnosis/validation/residual_metrics.h"

namespace gc {

enum class Channel { y, z };  ///< M_sy', M_sz'
constexpr std::array<Channel, 2> kChannels{Channel::y, Channel::z};
std::string_view to_string(Channel channel);  ///< "M_sy'", "M_sz'"

/// Both channels' errors.
struct ChannelErrors {
  ErrorAccumulator y, z;
  void add(const SensorMoments& measured, const SensorMoments& predicted);
  void merge(const ChannelErrors& other);
  const ErrorAccumulator& operator[](Channel channel) const { return channel == Channel::y ? y : z; }
  std::size_t count() const { return y.count(); }
};

enum class BinDimension { torque, misalignment, direction, loading, time };
constexpr std::array<BinDimension, 5> kBinDimensions{
    BinDimension::torque, BinDimension::misalignment, BinDimension::direction,
    BinDimension::loading, BinDimension::time};
std::string_view to_string(BinDimension dimension);  ///< "torque", "misalignment", ...
/// The sample's value along `dimension`, SI: T [N·m], zeta [rad], beta [rad], loading
/// direction (-1, 0, +1), time [s].
double bin_key(BinDimension dimension, const MeasurementSample& sample);

struct BinningOptions {
  double reference_torque_nm = 1.5e6;  ///< T_ref: torque bins span 0 .. torque_span x T_ref
  double jam_angle_rad = 0.0;          ///< xi: misalignment bins span 0 .. xi
  int torque_bins = 8;
  double torque_span = 1.6;            ///< of T_ref; larger torques fall in the last bin
  int misalignment_bins = 10;
  int direction_bins = 8;              ///< over (-pi, pi]
  int max_time_bins = 32;              ///< time bins double their width to stay within this
};

struct ErrorBin {
  double lower = 0.0;      ///< bin edges in the dimension's SI unit
  double upper = 0.0;
  double seen_min = 0.0;   ///< smallest and largest input seen in the bin
  double seen_max = 0.0;
  ChannelErrors errors;
};

/// Errors binned along one dimension. Out-of-range keys go to the first or last bin.
class ErrorBinning {
 public:
  ErrorBinning(BinDimension dimension, const BinningOptions& options);

  void add(const MeasurementSample& sample, const SensorMoments& measured,
           const SensorMoments& predicted);
  BinDimension dimension() const { return dimension_; }
  const std::vector<ErrorBin>& bins() const { return bins_; }
  /// Bin index of `key` (time bins may widen when a later time arrives).
  std::size_t index(double key);

 private:
  void widen_time_bins();

  BinDimension dimension_;
  std::size_t max_bins_;
  std::vector<ErrorBin> bins_;
  bool started_ = false;  // time: the first sample sets the origin
};

/// Errors on a torque x misalignment grid: cells[torque_bin * misalignment bins + column].
struct ErrorMap {
  ErrorBinning torque, misalignment;  // edges; their own errors are not used
  std::vector<ChannelErrors> cells;
  explicit ErrorMap(const BinningOptions& options);
  void add(const MeasurementSample& sample, const SensorMoments& measured,
           const SensorMoments& predicted);
  const ChannelErrors& cell(std::size_t torque_bin, std::size_t misalignment_bin) const;
};

/// Samples the model refused, by the field its error named, with the first example.
struct RejectionCount {
  std::size_t count = 0;
  double first_time_s = 0.0;
  std::string first_message;
};

/// Everything validate reports about one model on one recording, in constant memory.
class ValidationAccumulator {
 public:
  explicit ValidationAccumulator(const BinningOptions& options);

  void add(const RecordedSample& sample, const SensorMoments& predicted);
  void reject(const RecordedSample& sample, const std::string& field, std::string_view message);

  /// add() as kParts independent parts (the overall errors and the noise; each binning; the
  /// map): fed every sample in order, part by part, they hold the same bits as add(), so a
  /// caller may feed different parts on different threads.
  static constexpr std::size_t kParts = 2 + kBinDimensions.size();
  void add_part(std::size_t part, const RecordedSample& sample, const SensorMoments& predicted);

  const BinningOptions& options() const { return options_; }
  const ChannelErrors& overall() const { return overall_; }
  const std::vector<ErrorBinning>& binnings() const { return binnings_; }
  const ErrorBinning& binning(BinDimension dimension) const;
  const ErrorMap& map() const { return map_; }
  const std::map<std::string, RejectionCount>& rejections() const { return rejections_; }
  std::size_t rejected_count() const;
  /// The noise of `channel` estimated from successive errors, sqrt(mean((e_i - e_{i-1})^2) / 2):
  /// noise does not correlate from one sample to the next, a model error that varies slowly
  /// with the load does and cancels in the difference. Zero before two samples.
  double noise_estimate_nm(Channel channel) const;

 private:
  BinningOptions options_;
  ChannelErrors overall_;
  std::vector<ErrorBinning> binnings_;
  ErrorMap map_;
  std::map<std::string, RejectionCount> rejections_;
  std::optional<SensorMoments> last_error_;   // of the previous compared sample
  std::array<double, 2> difference_sum_sq_{};
  std::size_t differences_ = 0;
};

}  // namespace gc
