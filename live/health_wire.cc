#include "live/health_wire.h"

#include <algorithm>

#include "live/wire_text.h"
#include "protocol/dds_entity.h"

namespace gc::live {
namespace {

gearcoupling_ChannelHealth channel_wire(const ChannelFigures& figures) {
  return {figures.rmse_nm, figures.bias_nm, figures.noise_nm, figures.systematic_nm,
          figures.at_noise_level};
}

gearcoupling_ModelPeriod period_wire(const ModelPeriodReport& period) {
  return {lend(period.model_name), unix_seconds(period.since), period.in_force_s,
          period.evaluated, channel_wire(period.channels[0]), channel_wire(period.channels[1])};
}

}  // namespace

double unix_seconds(std::chrono::system_clock::time_point time) {
  return std::chrono::duration<double>(time.time_since_epoch()).count();
}

void write_health(dds_entity_t writer, const std::string& test_cell, std::uint64_t monitor_id,
                  bool stale, const HealthReport& report) {
  gearcoupling_CellHealth health{};
  set_test_cell(health.test_cell, test_cell);
  health.monitor_id = monitor_id;
  health.stale = stale;
  health.window_begin_s = report.window_begin_s;
  health.window_end_s = report.window_end_s;
  health.window_samples = report.window_samples;
  health.model = period_wire(report.model);
  gearcoupling_ModelPeriod previous{};
  if (report.previous_model) {
    previous = period_wire(*report.previous_model);
    health.previous_model = &previous;
  }
  health.worst_region = lend(report.worst_region);
  health.last_refusal = lend(report.last_refusal);
  health.last_model_refusal = lend(report.last_model_refusal);
  const SampleCountsSnapshot& c = report.counts;
  health.counts = {c.taken, c.evaluated, c.refused_not_finite, c.refused_by_model,
                   c.refused_out_of_order, c.lost, c.runs, c.unit_slip_batches};
  health.sample_rate_hz = report.sample_rate_hz;
  health.learning_state = lend(report.learning.state);
  health.learning = lend(report.learning.text);
  health.learning_samples_missing = report.learning.samples_missing;
  health.unit_error = lend(report.unit_error);
  if (report.proposal_rmse_nm) {
    health.proposal_msy_rmse_nm = (*report.proposal_rmse_nm)[0];
    health.proposal_msz_rmse_nm = (*report.proposal_rmse_nm)[1];
    health.proposal_samples = report.proposal_samples;
  }
  protocol::check_dds(dds_write(writer, &health), "dds_write(health)");
}

void dispose_health(dds_entity_t writer, const std::string& test_cell) {
  gearcoupling_CellHealth key{};
  set_test_cell(key.test_cell, test_cell);
  dds_dispose(writer, &key);
  // And forgotten: a TRANSIENT_LOCAL writer keeps a disposed instance for late readers until it
  // is unregistered, so test cells coming and going would grow the writer without bound.
  dds_unregister_instance(writer, &key);
}

}  // namespace gc::live
