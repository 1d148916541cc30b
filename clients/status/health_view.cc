#include "clients/status/health_view.h"

namespace gc::status {

HealthView health_view(const ::gearcoupling::v1::TestCellRecord& record) {
  HealthView v;
  v.test_cell = record.test_cell();
  v.stale = record.state() == "stale";
  v.disposed = record.state() == "gone";
  v.window_begin_s = record.window_begin_s();
  v.window_end_s = record.window_end_s();
  v.window_samples = record.window_samples();
  v.model_name = record.model().model_name();
  v.model_since_unix_s = record.model().since_unix_s();
  v.model_in_force_s = record.model().in_force_s();
  v.model_evaluated = record.model().evaluated();
  const ::gearcoupling::v1::ChannelHealthRecord* channels[2] = {&record.model().msy(),
                                                                &record.model().msz()};
  for (int c = 0; c < 2; ++c) {
    v.rmse_nm[c] = channels[c]->rmse_nm();
    v.bias_nm[c] = channels[c]->bias_nm();
    v.noise_nm[c] = channels[c]->noise_nm();
    v.systematic_nm[c] = channels[c]->systematic_nm();
    v.at_noise_level[c] = channels[c]->at_noise_level();
  }
  v.model_health = model_health_from(record.model_health());   // the board's, with hysteresis
  if (record.has_previous_model()) {
    v.previous_model_name = record.previous_model().model_name();
    v.previous_rmse_nm[0] = record.previous_model().msy().rmse_nm();
    v.previous_rmse_nm[1] = record.previous_model().msz().rmse_nm();
  }
  v.worst_region = record.worst_region();
  v.last_refusal = record.last_refusal();
  v.last_model_refusal = record.last_model_refusal();
  const auto& counts = record.counts();
  v.taken = counts.taken();
  v.evaluated = counts.evaluated();
  v.refused_not_finite = counts.refused_not_finite();
  v.refused_by_model = counts.refused_by_model();
  v.refused_out_of_order = counts.refused_out_of_order();
  v.lost = counts.lost();
  v.runs = counts.runs();
  v.unit_slip_batches = counts.unit_slip_batches();
  v.sample_rate_hz = record.sample_rate_hz();
  v.learning_state = record.learning_state();
  v.learning = record.learning();
  v.learning_samples_missing = record.learning_samples_missing();
  v.unit_error = record.unit_error();
  v.proposal_rmse_nm[0] = record.proposal_msy_rmse_nm();
  v.proposal_rmse_nm[1] = record.proposal_msz_rmse_nm();
  v.proposal_samples = record.proposal_samples();
  return v;
}

}  // namespace gc::status
