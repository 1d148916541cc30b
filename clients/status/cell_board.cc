#include "clients/status/cell_board.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cstring>

#include "gearcoupling.h"
#include "live/live_qos.h"
#include "live/live_topics.h"
#include "protocol/names.h"
#include "clients/status/listening_reader.h"
#include "clients/status/model_health.h"

namespace gc::status {

using protocol::check_dds;
using protocol::Entity;

std::string sample_text(const char* value, std::size_t max) {
  return value != nullptr ? std::string(value, strnlen(value, max)) : "";
}

namespace {

void copy_channel(const gearcoupling_ChannelHealth& in, v1::ChannelHealthRecord& out) {
  out.set_rmse_nm(in.rmse_nm);
  out.set_bias_nm(in.bias_nm);
  out.set_noise_nm(in.noise_nm);
  out.set_systematic_nm(in.systematic_nm);
  out.set_at_noise_level(in.at_noise_level);
}

void copy_period(const gearcoupling_ModelPeriod& in, v1::ModelPeriodRecord& out) {
  out.set_model_name(sample_text(in.model_name));
  out.set_since_unix_s(in.since_unix_s);
  out.set_in_force_s(in.in_force_s);
  out.set_evaluated(in.evaluated);
  copy_channel(in.msy, *out.mutable_msy());
  copy_channel(in.msz, *out.mutable_msz());
}

/// The health sample's members, into the record (state, age and residuals are the board's).
void copy_health(const gearcoupling_CellHealth& in, v1::TestCellRecord& out) {
  out.set_monitor_id(protocol::hex_id(in.monitor_id));
  out.set_window_begin_s(in.window_begin_s);
  out.set_window_end_s(in.window_end_s);
  out.set_window_samples(in.window_samples);
  copy_period(in.model, *out.mutable_model());
  if (in.previous_model != nullptr) {
    copy_period(*in.previous_model, *out.mutable_previous_model());
  } else {
    out.clear_previous_model();
  }
  out.set_worst_region(sample_text(in.worst_region));
  out.set_last_refusal(sample_text(in.last_refusal));
  out.set_last_model_refusal(sample_text(in.last_model_refusal));
  v1::SampleCountsRecord& counts = *out.mutable_counts();
  counts.set_taken(in.counts.taken);
  counts.set_evaluated(in.counts.evaluated);
  counts.set_refused_not_finite(in.counts.refused_not_finite);
  counts.set_refused_by_model(in.counts.refused_by_model);
  counts.set_refused_out_of_order(in.counts.refused_out_of_order);
  counts.set_lost(in.counts.lost);
  counts.set_runs(in.counts.runs);
  counts.set_unit_slip_batches(in.counts.unit_slip_batches);
  out.set_sample_rate_hz(in.sample_rate_hz);
  out.set_learning_state(sample_text(in.learning_state));
  out.set_learning(sample_text(in.learning));
  out.set_learning_samples_missing(in.learning_samples_missing);
  out.set_unit_error(sample_text(in.unit_error));
  out.set_proposal_msy_rmse_nm(in.proposal_msy_rmse_nm);
  out.set_proposal_msz_rmse_nm(in.proposal_msz_rmse_nm);
  out.set_proposal_samples(in.proposal_samples);
  // With hysteresis against the badge it showed (model_health.h); a unit error is not the
  // model's health, whatever the slipped moments say of it.
  const ModelHealth shown = model_health_from(out.model_health());
  const ModelHealth health = out.unit_error().empty() ? model_health(out.model(), in.window_samples, shown)
                                                       : ModelHealth::unit_error;
  out.set_model_health(std::string(to_string(health)));
}

}  // namespace

void CellBoard::Accumulator::add(double value, bool first) {
  min = first ? value : std::min(min, value);
  max = first ? value : std::max(max, value);
  sum = first ? value : sum + value;
}

v1::Envelope CellBoard::Accumulator::envelope(std::uint64_t count) const {
  v1::Envelope out;
  out.set_min(min);
  out.set_max(max);
  out.set_mean(count > 0 ? sum / static_cast<double>(count) : 0.0);
  return out;
}

CellBoard::CellBoard(dds_entity_t participant, CellBoardOptions options)
    : options_(options),
      health_topic_(live::make_health_topic(participant)),
      subscriber_(live::make_live_subscriber(participant)) {
  health_reader_ = make_listening_reader<&CellBoard::take_health>(
      subscriber_.get(), health_topic_.get(), live::health_reader_qos(), this,
      "dds_create_reader(health)");
  take_health();
  if (options_.read_residuals) {
    residual_topic_ = live::make_residual_topic(participant);
    residual_reader_ = make_listening_reader<&CellBoard::take_residuals>(
        subscriber_.get(), residual_topic_.get(), live::residual_qos(), this,
        "dds_create_reader(residual)");
    take_residuals();
  }
}

void CellBoard::take_health() {
  take_each_batch<gearcoupling_CellHealth>(health_reader_.get(), [this](const auto& samples) {
    const Clock::time_point now = Clock::now();
    std::lock_guard lock(mutex_);
    for (std::size_t i = 0; i < samples.size(); ++i) {
      const dds_sample_info_t& info = samples.info(i);
      if (info.valid_data) {
        const std::string cell = samples[i].test_cell;
        Entry* admitted = admit(cell, now);
        if (admitted == nullptr) continue;
        Entry& entry = *admitted;
        // A cell that was disposed and unregistered comes back under a new handle.
        if (entry.health_handle) health_handles_.erase(*entry.health_handle);
        health_handles_[info.instance_handle] = cell;
        entry.health_handle = info.instance_handle;
        entry.record.set_test_cell(cell);
        copy_health(samples[i], entry.record);
        entry.has_health = true;
        entry.monitor_says_stale = samples[i].stale;
        entry.health_received = now;
        entry.last_heard = now;
      }
      const auto handle = health_handles_.find(info.instance_handle);
      if (handle == health_handles_.end()) continue;
      Entry& entry = entries_.at(handle->second);
      entry.disposed = info.instance_state == DDS_IST_NOT_ALIVE_DISPOSED;
      entry.writer_lost = info.instance_state == DDS_IST_NOT_ALIVE_NO_WRITERS;
      if (info.instance_state != DDS_IST_ALIVE) entry.last_heard = now;
    }
  });
  health_arrived_.notify_all();
}

void CellBoard::take_residuals() {
  take_each_batch<gearcoupling_ResidualBatch>(residual_reader_.get(), [this](const auto& samples) {
    const Clock::time_point now = Clock::now();
    std::lock_guard lock(mutex_);
    for (std::size_t i = 0; i < samples.size(); ++i) {
      if (!samples.info(i).valid_data) continue;
      const gearcoupling_ResidualBatch& batch = samples[i];
      Entry* admitted = admit(batch.test_cell, now);
      if (admitted == nullptr) continue;
      Entry& entry = *admitted;
      entry.record.set_test_cell(batch.test_cell);
      entry.last_heard = now;
      Aggregate& aggregate = entry.aggregate;
      aggregate.model_name = sample_text(batch.model_name);
      aggregate.latest_published_ns = std::max(aggregate.latest_published_ns, batch.published_ns);
      for (uint32_t k = 0; k < batch.residuals._length; ++k) {
        const gearcoupling_Residual& r = batch.residuals._buffer[k];
        const bool first = aggregate.count == 0;
        if (first) aggregate.time_begin_s = r.time_s;
        aggregate.time_end_s = r.time_s;
        aggregate.msy_measured.add(r.msy_measured_nm, first);
        aggregate.msy_predicted.add(r.msy_predicted_nm, first);
        aggregate.msz_measured.add(r.msz_measured_nm, first);
        aggregate.msz_predicted.add(r.msz_predicted_nm, first);
        aggregate.count += 1;
      }
    }
  });
}

const char* CellBoard::state_of(const Entry& entry, Clock::time_point now) const {
  const bool old = !entry.has_health || now - entry.health_received > options_.stale_after;
  if (entry.disposed) return "gone";
  return entry.writer_lost || entry.monitor_says_stale || (entry.has_health && old) ? "stale"
                                                                                    : "alive";
}

CellBoard::Entry* CellBoard::admit(const std::string& cell, Clock::time_point now) {
  if (!options_.only_cell.empty() && cell != options_.only_cell) return nullptr;
  const auto found = entries_.find(cell);
  if (found != entries_.end()) return &found->second;
  if (entries_.size() >= options_.max_cells) {
    // Live cells keep their places; the gone or stale one heard from longest ago makes room.
    auto oldest = entries_.end();
    for (auto it = entries_.begin(); it != entries_.end(); ++it) {
      if (state_of(it->second, now)[0] == 'a') continue;
      if (oldest == entries_.end() || it->second.last_heard < oldest->second.last_heard) oldest = it;
    }
    if (oldest == entries_.end()) {
      if (refused_++ == 0) {
        spdlog::warn("test cell {} ignored: {} cells are on the board, all alive, the most "
                     "--max-cells allows; further ones are counted "
                     "(gearcoupling_dashboard_cells_refused_total), not logged",
                     cell, options_.max_cells);
      }
      return nullptr;
    }
    forget(oldest);
  }
  return &entries_[cell];
}

std::map<std::string, CellBoard::Entry>::iterator CellBoard::forget(
    std::map<std::string, Entry>::iterator it) {
  if (it->second.health_handle) health_handles_.erase(*it->second.health_handle);
  return entries_.erase(it);
}

std::uint64_t CellBoard::refused() {
  std::lock_guard lock(mutex_);
  return refused_;
}

std::size_t CellBoard::size() {
  std::lock_guard lock(mutex_);
  return entries_.size();
}

std::optional<v1::TestCellRecord> CellBoard::health_record_locked(const std::string& cell,
                                                                 Clock::time_point now) const {
  const auto found = entries_.find(cell);
  if (found == entries_.end() || !found->second.has_health) return std::nullopt;
  v1::TestCellRecord record = found->second.record;
  record.set_state(state_of(found->second, now));
  record.set_health_age_s(std::chrono::duration<double>(now - found->second.health_received).count());
  return record;
}

std::optional<HealthView> CellBoard::latest(const std::string& test_cell) {
  std::lock_guard lock(mutex_);
  const auto record = health_record_locked(test_cell, Clock::now());
  if (!record) return std::nullopt;
  return health_view(*record);
}

std::optional<HealthView> CellBoard::wait_for(const std::string& test_cell,
                                              const std::function<bool(const HealthView&)>& ready,
                                              std::chrono::milliseconds timeout) {
  const Clock::time_point deadline = Clock::now() + timeout;
  std::unique_lock lock(mutex_);
  for (;;) {
    const Clock::time_point now = Clock::now();
    const auto record = health_record_locked(test_cell, now);
    std::optional<HealthView> health;
    if (record) health = health_view(*record);
    if ((health && ready(*health)) || now >= deadline) return health;
    // A state turns stale with time alone, so look again at least every 100 ms.
    health_arrived_.wait_until(lock, std::min(deadline, now + std::chrono::milliseconds(100)));
  }
}

std::vector<v1::TestCellRecord> CellBoard::snapshot() { return collect(false); }

std::vector<v1::TestCellRecord> CellBoard::drain() { return collect(true); }

std::vector<v1::TestCellRecord> CellBoard::collect(bool drain) {
  const Clock::time_point now = Clock::now();
  std::vector<v1::TestCellRecord> cells;
  std::lock_guard lock(mutex_);
  for (auto it = entries_.begin(); it != entries_.end();) {
    Entry& entry = it->second;
    const char* state = state_of(entry, now);
    if (state[0] != 'a' && now - entry.last_heard > options_.forget_after) {
      it = forget(it);
      continue;
    }
    v1::TestCellRecord& record = cells.emplace_back(entry.record);
    record.set_state(state);
    if (!entry.has_health) record.set_model_health(std::string(to_string(ModelHealth::unknown)));
    record.set_health_age_s(
        entry.has_health ? std::chrono::duration<double>(now - entry.health_received).count() : -1.0);
    if (drain && entry.aggregate.count > 0) {
      const Aggregate& a = entry.aggregate;
      v1::ResidualAggregate& out = *record.add_residuals();
      out.set_residuals(a.count);
      out.set_time_begin_s(a.time_begin_s);
      out.set_time_end_s(a.time_end_s);
      out.set_model_name(a.model_name);
      *out.mutable_msy_measured_nm() = a.msy_measured.envelope(a.count);
      *out.mutable_msy_predicted_nm() = a.msy_predicted.envelope(a.count);
      *out.mutable_msz_measured_nm() = a.msz_measured.envelope(a.count);
      *out.mutable_msz_predicted_nm() = a.msz_predicted.envelope(a.count);
      out.set_latest_published_unix_s(static_cast<double>(a.latest_published_ns) * 1e-9);
      entry.aggregate = Aggregate{};
    }
    ++it;
  }
  return cells;
}

}  // namespace gc::status
