#include "diagnosis/validation/error_bins.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/model_error.h"

namespace gc {
namespace {

// Seconds covered by one time bin before the first widening: fine enough for short recordings,
// and doubling keeps even a day-long one within max_time_bins after ~20 widenings.
constexpr double kFirstTimeBinWidthS = 1e-3;

std::vector<ErrorBin> equal_bins(double lower, double upper, int count) {
  std::vector<ErrorBin> bins(static_cast<std::size_t>(count));
  const double width = (upper - lower) / count;
  for (std::size_t i = 0; i < bins.size(); ++i) {
    bins[i].lower = lower + width * static_cast<double>(i);
    bins[i].upper = lower + width * static_cast<double>(i + 1);
  }
  return bins;
}

std::vector<ErrorBin> initial_bins(BinDimension dimension, const BinningOptions& o) {
  switch (dimension) {
    case BinDimension::torque:
      return equal_bins(0.0, o.torque_span * o.reference_torque_nm, o.torque_bins);
    case BinDimension::misalignment: return equal_bins(0.0, o.jam_angle_rad, o.misalignment_bins);
    case BinDimension::direction:
      return equal_bins(-std::numbers::pi, std::numbers::pi, o.direction_bins);
    case BinDimension::loading: return equal_bins(-1.5, 1.5, 3);
    case BinDimension::time: return equal_bins(0.0, kFirstTimeBinWidthS, 1);
  }
  return {};
}

void note_seen(ErrorBin& bin, double key) {
  if (bin.errors.count() == 0) {
    bin.seen_min = bin.seen_max = key;
  } else {
    bin.seen_min = std::min(bin.seen_min, key);
    bin.seen_max = std::max(bin.seen_max, key);
  }
}

void validate(const BinningOptions& o) {
  require_positive("binning.reference_torque_nm", o.reference_torque_nm);
  require_positive("binning.jam_angle_rad", o.jam_angle_rad);
  require_positive("binning.torque_span", o.torque_span);
  for (int count : {o.torque_bins, o.misalignment_bins, o.direction_bins, o.max_time_bins}) {
    if (count < 2) throw InvalidInput("binning", count, "bin counts >= 2");
  }
}

}  // namespace

std::string_view to_string(Channel channel) { return channel == Channel::y ? "M_sy'" : "M_sz'"; }

void ChannelErrors::add(const SensorMoments& measured, const SensorMoments& predicted) {
  y.add(measured.y_nm, predicted.y_nm);
  z.add(measured.z_nm, predicted.z_nm);
}

void ChannelErrors::merge(const ChannelErrors& other) {
  y.merge(other.y);
  z.merge(other.z);
}

std::string_view to_string(BinDimension dimension) {
  switch (dimension) {
    case BinDimension::torque: return "torque";
    case BinDimension::misalignment: return "misalignment";
    case BinDimension::direction: return "direction";
    case BinDimension::loading: return "loading";
    case BinDimension::time: return "time";
  }
  return "";
}

double bin_key(BinDimension dimension, const MeasurementSample& sample) {
  switch (dimension) {
    case BinDimension::torque: return sample.torque_nm;
    case BinDimension::misalignment: return sample.misalignment_rad;
    case BinDimension::direction: return sample.direction_rad;
    case BinDimension::loading: return sample.loading_direction;
    case BinDimension::time: return sample.time_s;
  }
  return 0.0;
}

ErrorBinning::ErrorBinning(BinDimension dimension, const BinningOptions& options)
    : dimension_(dimension),
      max_bins_(static_cast<std::size_t>(options.max_time_bins)),
      bins_(initial_bins(dimension, options)) {}

void ErrorBinning::widen_time_bins() {
  // Pairs of bins become one bin of twice the width; the count halves (rounded up).
  std::vector<ErrorBin> wider((bins_.size() + 1) / 2);
  const double width = 2.0 * (bins_[0].upper - bins_[0].lower);
  const double origin = bins_[0].lower;
  for (std::size_t i = 0; i < wider.size(); ++i) {
    wider[i].lower = origin + width * static_cast<double>(i);
    wider[i].upper = origin + width * static_cast<double>(i + 1);
    for (std::size_t j = 2 * i; j < std::min(bins_.size(), 2 * i + 2); ++j) {
      if (bins_[j].errors.count() == 0) continue;
      note_seen(wider[i], bins_[j].seen_min);
      note_seen(wider[i], bins_[j].seen_max);
      wider[i].errors.merge(bins_[j].errors);
    }
  }
  bins_ = std::move(wider);
}

std::size_t ErrorBinning::index(double key) {
  if (dimension_ == BinDimension::time) {
    if (!started_) {
      started_ = true;
      const double width = bins_[0].upper - bins_[0].lower;
      bins_[0].lower = key;
      bins_[0].upper = key + width;
    }
    const double width = bins_[0].upper - bins_[0].lower;
    auto position = std::floor((key - bins_[0].lower) / width);
    while (position >= static_cast<double>(max_bins_)) {
      widen_time_bins();
      position = std::floor((key - bins_[0].lower) / (bins_[0].upper - bins_[0].lower));
    }
    const auto i = static_cast<std::size_t>(std::max(0.0, position));
    while (bins_.size() <= i) {
      ErrorBin next;
      next.lower = bins_.back().upper;
      next.upper = next.lower + (bins_[0].upper - bins_[0].lower);
      bins_.push_back(next);
    }
    return i;
  }
  const double lower = bins_.front().lower;
  const double width = bins_.front().upper - lower;
  const double position = std::floor((key - lower) / width);
  return static_cast<std::size_t>(
      std::clamp(position, 0.0, static_cast<double>(bins_.size() - 1)));
}

void ErrorBinning::add(const MeasurementSample& sample, const SensorMoments& measured,
                       const SensorMoments& predicted) {
  const double key = bin_key(dimension_, sample);
  ErrorBin& bin = bins_[index(key)];
  note_seen(bin, key);
  bin.errors.add(measured, predicted);
}

ErrorMap::ErrorMap(const BinningOptions& options)
    : torque(BinDimension::torque, options),
      misalignment(BinDimension::misalignment, options),
      cells(torque.bins().size() * misalignment.bins().size()) {}

void ErrorMap::add(const MeasurementSample& sample, const SensorMoments& measured,
                   const SensorMoments& predicted) {
  const std::size_t row = torque.index(sample.torque_nm);
  const std::size_t column = misalignment.index(sample.misalignment_rad);
  cells[row * misalignment.bins().size() + column].add(measured, predicted);
}

const ChannelErrors& ErrorMap::cell(std::size_t torque_bin, std::size_t misalignment_bin) const {
  return cells.at(torque_bin * misalignment.bins().size() + misalignment_bin);
}

ValidationAccumulator::ValidationAccumulator(const BinningOptions& options)
    : options_((validate(options), options)), map_(options) {
  for (BinDimension dimension : kBinDimensions) binnings_.emplace_back(dimension, options);
}

void ValidationAccumulator::add(const RecordedSample& sample, const SensorMoments& predicted) {
  for (std::size_t part = 0; part < kParts; ++part) add_part(part, sample, predicted);
}

void ValidationAccumulator::add_part(std::size_t part, const RecordedSample& sample,
                                     const SensorMoments& predicted) {
  if (part > 1) {
    binnings_[part - 2].add(sample.input, sample.measured, predicted);
  } else if (part == 1) {
    map_.add(sample.input, sample.measured, predicted);
  } else {
    overall_.add(sample.measured, predicted);
    const SensorMoments error{predicted.y_nm - sample.measured.y_nm,
                              predicted.z_nm - sample.measured.z_nm};
    if (last_error_) {
      const double dy = error.y_nm - last_error_->y_nm, dz = error.z_nm - last_error_->z_nm;
      difference_sum_sq_[0] += dy * dy;
      difference_sum_sq_[1] += dz * dz;
      ++differences_;
    }
    last_error_ = error;
  }
}

double ValidationAccumulator::noise_estimate_nm(Channel channel) const {
  if (differences_ == 0) return 0.0;
  const double sum = difference_sum_sq_[channel == Channel::y ? 0 : 1];
  return std::sqrt(sum / (2.0 * static_cast<double>(differences_)));
}

void ValidationAccumulator::reject(const RecordedSample& sample, const std::string& field,
                                   std::string_view message) {
  RejectionCount& entry = rejections_[field];
  if (entry.count++ == 0) {
    entry.first_time_s = sample.input.time_s;
    entry.first_message = message;
  }
}

const ErrorBinning& ValidationAccumulator::binning(BinDimension dimension) const {
  return binnings_.at(static_cast<std::size_t>(dimension));
}

std::size_t ValidationAccumulator::rejected_count() const {
  std::size_t total = 0;
  for (const auto& [field, entry] : rejections_) total += entry.count;
  return total;
}

}  // namespace gc
