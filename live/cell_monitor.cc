#include "live/cell_monitor.h"

#include <cmath>

#include "analysis/validation_summary.h"
#include "core/model_error.h"
#include "diagnosis/validation/worst_regions.h"

namespace gc::live {

CellMonitor::CellMonitor(CellModel model, const CellMonitorOptions& options)
    : options_(options),
      model_(std::move(model)),
      windows_{Window{ValidationAccumulator(binning())}, Window{ValidationAccumulator(binning())}},
      recent_(options.diagnosis_samples, options.diagnosis_window_s) {}

BinningOptions CellMonitor::binning() const {
  BinningOptions binning;
  binning.reference_torque_nm = options_.reference_torque_nm;
  binning.jam_angle_rad = model_.model->geometry().jam_angle().angle_rad;
  return binning;
}

void CellMonitor::restart_windows() {
  window_origin_s_.reset();
  for (Window& window : windows_) window = Window{ValidationAccumulator(binning())};
}

SampleOutcome CellMonitor::take(std::uint64_t run_id, std::uint64_t sequence_number,
                                std::optional<RecordedSample> sample, const std::string& refusal,
                                SensorMoments& predicted) {
  ++counts_.taken;
  if (run_id != run_id_) {
    // A publisher (re)started: its time may start anywhere. Samples it sent before this
    // monitor joined were never this monitor's to lose, so gaps count from here.
    ++counts_.runs;
    run_id_ = run_id;
    last_sequence_ = sequence_number > 0 ? sequence_number - 1 : 0;   // 0 is refused below
    last_time_s_.reset();
    derived_.emplace(options_.loading_dead_band_rad, options_.still_after_s);
    restart_windows();
    recent_.clear();
  }
  if (sequence_number <= last_sequence_ ||
      (sample && last_time_s_ && sample->input.time_s < *last_time_s_)) {
    ++counts_.refused_out_of_order;
    last_refusal_ = sequence_number <= last_sequence_
                        ? "measurement.sequence_number: " + std::to_string(sequence_number) +
                              " after " + std::to_string(last_sequence_)
                        : "measurement.time_s: went back in time within run";
    return SampleOutcome::refused_out_of_order;
  }
  counts_.lost += sequence_number - last_sequence_ - 1;
  last_sequence_ = sequence_number;
  if (!sample) {
    ++counts_.refused_not_finite;
    last_refusal_ = refusal;
    return SampleOutcome::refused_not_finite;
  }
  last_time_s_ = sample->input.time_s;
  derived_->next(sample->input);
  try {
    predicted = model_.model->predict(sample->input).moments;
  } catch (const InvalidInput& error) {
    ++counts_.refused_by_model;
    last_refusal_ = error.field() + ": " + error.what();
    for (Window& window : windows_) {
      if (window.begin_s) window.validation.reject(*sample, error.field(), error.what());
    }
    return SampleOutcome::refused_by_model;
  } catch (const ModelError& error) {
    ++counts_.refused_by_model;
    last_refusal_ = std::string("model: ") + error.what();
    return SampleOutcome::refused_by_model;
  }
  ++counts_.evaluated;
  ++evaluated_under_model_;
  add_to_windows(*sample, predicted);
  recent_.add(*sample);
  return SampleOutcome::evaluated;
}

void CellMonitor::add_to_windows(const RecordedSample& sample, const SensorMoments& predicted) {
  const double t = sample.input.time_s;
  std::optional<SensorMoments> shadow;
  if (shadow_) {
    try {
      shadow = shadow_->predict(sample.input).moments;
    } catch (const ModelError&) {
      // The proposal refuses what the model in force takes: left out of its figures.
    }
  }
  if (!window_origin_s_) window_origin_s_ = t;
  for (std::size_t i = 0; i < windows_.size(); ++i) {
    Window& window = windows_[i];
    if (!window.begin_s) {
      if (t < *window_origin_s_ + 0.5 * options_.window_s * static_cast<double>(i)) continue;
      window.begin_s = t;
    } else if (t - *window.begin_s >= options_.window_s) {
      window = Window{ValidationAccumulator(binning()), t, t};
    }
    window.validation.add(sample, predicted);
    window.scale.add(sample.measured, predicted);
    if (shadow) {
      const double ey = shadow->y_nm - sample.measured.y_nm, ez = shadow->z_nm - sample.measured.z_nm;
      window.shadow_sum_sq[0] += ey * ey;
      window.shadow_sum_sq[1] += ez * ez;
      ++window.shadow_count;
    }
    window.end_s = t;
  }
}

const CellMonitor::Window& CellMonitor::reported_window() const {
  const Window& a = windows_[0];
  const Window& b = windows_[1];
  if (!b.begin_s) return a;
  if (!a.begin_s) return b;
  return *a.begin_s <= *b.begin_s ? a : b;
}

namespace {
// A channel's RMSE at least this many times its noise: beyond "far off" (3 x).
constexpr double kSlipOverNoise = 10.0;
}  // namespace

std::optional<std::string> CellMonitor::unit_slip() const {
  const Window& window = reported_window();
  if (window.validation.overall().count() < kSamplesForUnitCheck) return std::nullopt;
  std::optional<std::string> refusal = window.scale.refusal(model_.name);
  if (!refusal) return refusal;
  // Only an error far above the noise is a slip: an aligned, unloaded cell's noise against a
  // model near zero can be 1000 times it too, and no unit is at fault there.
  for (Channel channel : kChannels) {
    if (window.validation.overall()[channel].metrics().rmse_nm >=
        kSlipOverNoise * window.validation.noise_estimate_nm(channel)) {
      return refusal;
    }
  }
  return std::nullopt;
}

void CellMonitor::end_batch() {
  if (unit_slip()) ++counts_.unit_slip_batches;
}

ModelPeriodReport CellMonitor::period(std::chrono::system_clock::time_point now) const {
  ModelPeriodReport report;
  report.model_name = model_.name;
  report.since = model_.since;
  report.in_force_s = std::chrono::duration<double>(now - model_.since).count();
  report.evaluated = evaluated_under_model_;
  const ValidationAccumulator& validation = reported_window().validation;
  for (Channel channel : kChannels) {
    const ErrorMetrics metrics = validation.overall()[channel].metrics();
    const ErrorSignature signature = error_signature(validation, channel);
    report.channels[static_cast<std::size_t>(channel)] = {
        metrics.rmse_nm, metrics.bias_nm, signature.noise_estimate_nm,
        signature.systematic_rms_nm, signature.at_noise_level};
  }
  return report;
}

void CellMonitor::shadow(std::shared_ptr<const CouplingModel> model) { shadow_ = std::move(model); }

void CellMonitor::swap_model(CellModel model) {
  const auto now = std::chrono::system_clock::now();
  previous_model_ = period(now);
  model_ = std::move(model);
  model_.since = now;
  evaluated_under_model_ = 0;
  shadow_.reset();   // a proposal is about the model replaced
  restart_windows();
}

namespace {

// validate's sentence for the worst region of the channel with the larger systematic error,
// "" when both are at the noise level or no region stands out.
std::string worst_region_text(const ValidationAccumulator& validation) {
  std::optional<ErrorSignature> worst;
  for (Channel channel : kChannels) {
    const ErrorSignature signature = error_signature(validation, channel);
    if (signature.at_noise_level) continue;
    if (!worst || signature.systematic_rms_nm > worst->systematic_rms_nm) worst = signature;
  }
  if (!worst) return "";
  for (const RegionError& region : worst_regions(validation, worst->channel)) {
    if (region.contrast >= analysis::kNotableContrast) return describe(region);
  }
  return "";
}

}  // namespace

HealthReport CellMonitor::health(std::chrono::system_clock::time_point now) const {
  HealthReport report;
  const Window& window = reported_window();
  report.window_begin_s = window.begin_s.value_or(0.0);
  report.window_end_s = window.end_s;
  report.window_samples = window.validation.overall().count();
  const double span_s = report.window_end_s - report.window_begin_s;
  if (report.window_samples >= 2 && span_s > 0.0) {
    report.sample_rate_hz = static_cast<double>(report.window_samples - 1) / span_s;
  }
  report.model = period(now);
  report.previous_model = previous_model_;
  report.unit_slip = unit_slip();
  // Under a unit slip every region errs: a region's sentence would send the reader after the
  // model ("errs most at medium misalignment") when the unit is at fault.
  if (report.window_samples >= 2 && !report.unit_slip) {
    report.worst_region = worst_region_text(window.validation);
  }
  report.last_refusal = last_refusal_;
  report.last_model_refusal = last_model_refusal_;
  if (shadow_ && window.shadow_count > 0) {
    const double n = static_cast<double>(window.shadow_count);
    report.proposal_rmse_nm = {std::sqrt(window.shadow_sum_sq[0] / n), std::sqrt(window.shadow_sum_sq[1] / n)};
    report.proposal_samples = window.shadow_count;
  }
  report.counts = counts_;
  return report;
}

}  // namespace gc::live
