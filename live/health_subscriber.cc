#include "live/health_subscriber.h"

#include <thread>

#include "gearcoupling.h"
#include "live/live_qos.h"
#include "live/live_topics.h"
#include "protocol/samples.h"

namespace gc::live {

namespace {

HealthView view_of(const gearcoupling_CellHealth& h) {
  HealthView v;
  v.test_cell = h.test_cell;
  v.stale = h.stale;
  v.window_begin_s = h.window_begin_s;
  v.window_end_s = h.window_end_s;
  v.window_samples = h.window_samples;
  v.model_name = h.model.model_name;
  v.model_since_unix_s = h.model.since_unix_s;
  v.model_in_force_s = h.model.in_force_s;
  v.model_evaluated = h.model.evaluated;
  const gearcoupling_ChannelHealth* channels[2] = {&h.model.msy, &h.model.msz};
  for (int c = 0; c < 2; ++c) {
    v.rmse_nm[c] = channels[c]->rmse_nm;
    v.bias_nm[c] = channels[c]->bias_nm;
    v.noise_nm[c] = channels[c]->noise_nm;
    v.systematic_nm[c] = channels[c]->systematic_nm;
    v.at_noise_level[c] = channels[c]->at_noise_level;
  }
  if (h.previous_model != nullptr) {
    v.previous_model_name = h.previous_model->model_name;
    v.previous_rmse_nm[0] = h.previous_model->msy.rmse_nm;
    v.previous_rmse_nm[1] = h.previous_model->msz.rmse_nm;
  }
  v.worst_region = h.worst_region;
  v.last_refusal = h.last_refusal;
  v.last_model_refusal = h.last_model_refusal;
  v.taken = h.counts.taken;
  v.evaluated = h.counts.evaluated;
  v.refused_not_finite = h.counts.refused_not_finite;
  v.refused_by_model = h.counts.refused_by_model;
  v.refused_out_of_order = h.counts.refused_out_of_order;
  v.lost = h.counts.lost;
  v.runs = h.counts.runs;
  return v;
}

}  // namespace

HealthSubscriber::HealthSubscriber(dds_entity_t participant)
    : subscriber_(make_live_subscriber(participant)), topic_(make_health_topic(participant)) {
  const protocol::Qos qos = health_reader_qos();
  reader_ = protocol::Entity(protocol::check_dds(
      dds_create_reader(subscriber_.get(), topic_.get(), qos.get(), nullptr),
      "dds_create_reader(health)"));
}

void HealthSubscriber::take() {
  for (;;) {
    protocol::LoanedSamples<gearcoupling_CellHealth, 16> samples(reader_.get());
    if (samples.size() == 0) return;
    for (std::size_t i = 0; i < samples.size(); ++i) {
      const dds_sample_info_t& info = samples.info(i);
      if (info.valid_data) {
        HealthView view = view_of(samples[i]);
        latest_[view.test_cell] = std::move(view);
      } else {
        // Dispose or unregister: the key is valid, the rest is not.
        const std::string cell = samples[i].test_cell;
        if (latest_.count(cell) != 0) latest_[cell].disposed = true;
      }
    }
  }
}

std::optional<HealthView> HealthSubscriber::latest(const std::string& test_cell) {
  take();
  const auto found = latest_.find(test_cell);
  if (found == latest_.end()) return std::nullopt;
  return found->second;
}

std::optional<HealthView> HealthSubscriber::wait_for(
    const std::string& test_cell, const std::function<bool(const HealthView&)>& ready,
    std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    std::optional<HealthView> health = latest(test_cell);
    if (health && ready(*health)) return health;
    if (std::chrono::steady_clock::now() >= deadline) return health;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
}

}  // namespace gc::live
