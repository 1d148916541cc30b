// One test cell under the monitor, without DDS: its model, the run it is in, the samples it
// took and refused, and the model's health over a rolling window of measurement time, measured
// as `validate` measures a recording (diagnosis/validation/). The monitor (live/monitor.h) keeps one
// per test cell and feeds it from the measurement topic.
#pragma once

#include <array>
#include <chrono>
#include <cstdint>
#include <optional>
#include <string>

#include "analysis/derived_inputs.h"
#include "analysis/scale_check.h"
#include "core/recorded_sample.h"
#include "diagnosis/validation/error_bins.h"
#include "live/cell_model.h"
#include "live/learning_status.h"
#include "live/sample_window.h"

namespace gc::live {

struct CellMonitorOptions {
  /// Health window in measurement time [s]: two windows, offset by half of it, each restarting
  /// every window_s; health reports the older, so it always spans window_s/2 to window_s.
  double window_s = 10.0;
  double reference_torque_nm = 1.5e6;   ///< T_ref of validate's wording [N·m]
  /// The loading direction's dead band [rad]: a live stream's noise is not known before it
  /// ends, so it is configured (docs/recordings.md has the trade-off). The default is wider
  /// than a clean recording's floor (LoadingDirectionOptions::min_dead_band_rad): 3.3e-6 rad of
  /// sensor noise keeps it (6 sigma) from reading a hold as travel.
  double loading_dead_band_rad = 2e-5;
  double still_after_s = LoadingDirectionOptions{}.still_after_s;   ///< [s]
  /// The rolling window the monitor's diagnosis runs on (live/sample_window.h): at most this
  /// many evaluated samples of the current run, spanning at least diagnosis_window_s [s].
  std::size_t diagnosis_samples = 2000;
  double diagnosis_window_s = 10.0;
};

/// What happened to one sample.
enum class SampleOutcome { evaluated, refused_not_finite, refused_by_model, refused_out_of_order };

/// Samples a window must hold before its moments' scale is judged: a 1000-fold slip shows in a
/// handful, and a 1 Hz cell's 10 s window holds 5 to 10.
inline constexpr std::uint64_t kSamplesForUnitCheck = 5;

struct SampleCountsSnapshot {
  std::uint64_t taken = 0, evaluated = 0, refused_not_finite = 0, refused_by_model = 0,
                refused_out_of_order = 0, lost = 0, runs = 0, unit_slip_batches = 0;
};

struct ChannelFigures {
  double rmse_nm = 0.0, bias_nm = 0.0, noise_nm = 0.0, systematic_nm = 0.0;  ///< [N·m]
  bool at_noise_level = false;
};

struct ModelPeriodReport {
  std::string model_name;
  std::chrono::system_clock::time_point since;
  double in_force_s = 0.0;          ///< [s]
  std::uint64_t evaluated = 0;
  std::array<ChannelFigures, 2> channels;   ///< M_sy', M_sz' over the window
};

struct HealthReport {
  double window_begin_s = 0.0, window_end_s = 0.0;   ///< measurement time [s]
  std::uint64_t window_samples = 0;
  /// Evaluated samples per second of measurement time over the window; 0 under 2 samples [Hz].
  double sample_rate_hz = 0.0;
  ModelPeriodReport model;
  std::optional<ModelPeriodReport> previous_model;
  std::string worst_region;        ///< validate's sentence, "" when none stands out
  std::string last_refusal;        ///< "field: message"
  std::string last_model_refusal;
  /// The unit check's finding on the window's moments (analysis::MomentScale::refusal, as
  /// validate's): nullopt when none, or under kSamplesForUnitCheck samples.
  std::optional<std::string> unit_slip;
  std::string unit_error;          ///< set by the monitor: unit_slip worded with its fix
  SampleCountsSnapshot counts;
  LearningStatus learning;         ///< set by the monitor (live/learning_status.h)
  /// The standing proposal's model over the same window as `model` (CellMonitor::shadow): RMSE
  /// per channel [N·m] and the samples it saw (fewer when it stood for part of the window only).
  std::optional<std::array<double, 2>> proposal_rmse_nm;
  std::uint64_t proposal_samples = 0;
};

class CellMonitor {
 public:
  CellMonitor(CellModel model, const CellMonitorOptions& options);

  /// Takes sample `sequence_number` of run `run_id` (`sample` nullopt when the wire sample had
  /// a non-finite member, `refusal` then says which). A new run restarts the sequence, the time
  /// and the health window. Sets `predicted` when the sample was evaluated.
  SampleOutcome take(std::uint64_t run_id, std::uint64_t sequence_number,
                     std::optional<RecordedSample> sample, const std::string& refusal,
                     SensorMoments& predicted);

  /// Puts `model` in force from the next sample; the current one becomes the previous model,
  /// its health frozen as it stood.
  void swap_model(CellModel model);
  void refuse_model(std::string reason) { last_model_refusal_ = std::move(reason); }

  HealthReport health(std::chrono::system_clock::time_point now) const;
  /// After each measurement batch: counts it when the window's moments show a unit slip.
  void end_batch();
  /// Also predicts every evaluated sample with `model` (a standing proposal's; nullptr: none),
  /// over the same health windows, so "now" and "with it" are read on one window (issue 39).
  void shadow(std::shared_ptr<const CouplingModel> model);
  const CellModel& model() const { return model_; }
  /// The latest evaluated samples of the current run, derived inputs filled in.
  const SampleWindow& recent_samples() const { return recent_; }
  std::uint64_t run_id() const { return run_id_; }

 private:
  struct Window {
    ValidationAccumulator validation;
    std::optional<double> begin_s = std::nullopt;
    double end_s = 0.0;
    analysis::MomentScale scale = {};   ///< measured against predicted RMS: the unit check
    std::array<double, 2> shadow_sum_sq = {0.0, 0.0};   ///< the shadow model's errors [N²·m²]
    std::uint64_t shadow_count = 0;
  };
  void restart_windows();
  void add_to_windows(const RecordedSample& sample, const SensorMoments& predicted);
  const Window& reported_window() const;
  std::optional<std::string> unit_slip() const;
  ModelPeriodReport period(std::chrono::system_clock::time_point now) const;
  BinningOptions binning() const;

  CellMonitorOptions options_;
  CellModel model_;
  std::uint64_t evaluated_under_model_ = 0;
  std::shared_ptr<const CouplingModel> shadow_;
  std::optional<ModelPeriodReport> previous_model_;
  std::uint64_t run_id_ = 0;
  std::uint64_t last_sequence_ = 0;
  std::optional<double> last_time_s_;
  std::optional<analysis::DerivedInputs> derived_;
  std::optional<double> window_origin_s_;
  std::array<Window, 2> windows_;
  SampleWindow recent_;
  SampleCountsSnapshot counts_;
  std::string last_refusal_, last_model_refusal_;
};

}  // namespace gc::live
