#include "live/monitor.h"

#include <spdlog/spdlog.h>

#include <vector>

#include "core/model_error.h"
#include "gearcoupling.h"
#include "live/health_wire.h"
#include "live/live_names.h"
#include "live/live_qos.h"
#include "live/live_topics.h"
#include "live/measurement_wire.h"
#include "protocol/random_id.h"
#include "protocol/samples.h"

namespace gc::live {

using protocol::check_dds;
using protocol::Entity;
using Clock = std::chrono::steady_clock;

struct Monitor::Cell {
  CellMonitor monitor;
  Clock::time_point last_sample = Clock::now();
  std::uint64_t decimation_count = 0;
  std::vector<gearcoupling_Residual> residuals = {};
};

namespace {

Entity make_writer(dds_entity_t publisher, dds_entity_t topic, const protocol::Qos& qos,
                   const char* what) {
  return Entity(check_dds(dds_create_writer(publisher, topic, qos.get(), nullptr), what));
}

std::uint64_t realtime_ns() {
  return static_cast<std::uint64_t>(std::chrono::duration_cast<std::chrono::nanoseconds>(
                                        std::chrono::system_clock::now().time_since_epoch())
                                        .count());
}

}  // namespace

Monitor::Monitor(const MonitorOptions& options)
    : options_(options),
      monitor_id_(protocol::random_id()),
      default_model_(load_cell_model(options.default_model, options.models_dir, options.catalog_dir)) {
  for (const auto& [test_cell, model] : options.cell_models) {
    require_test_cell_name(test_cell);
    models_.emplace(test_cell, load_cell_model(model, options.models_dir, options.catalog_dir));
  }
  participant_ = Entity(protocol::create_participant(options.domain, protocol::dds_config()));
  const dds_entity_t participant = participant_.get();
  // Measurements and swaps: every test cell's own partition, and the shared one of older
  // publishers (docs/protocol.md, "The live test cell").
  subscriber_ = make_subscriber_in(participant, {kLivePartition, kEveryCellPartition});
  publisher_ = make_live_publisher(participant);
  measurement_topic_ = make_measurement_topic(participant);
  residual_topic_ = make_residual_topic(participant);
  health_topic_ = make_health_topic(participant);
  model_topic_ = make_model_topic(participant);
  // A writer's partitions are learnt as it matches (remember_writer), so the check of every
  // sample's partition never depends on the writer still being there when the sample is taken.
  dds_listener_t* listener = dds_create_listener(this);
  dds_lset_subscription_matched(
      listener, [](dds_entity_t reader, const dds_subscription_matched_status_t status, void* self) {
        if (status.current_count_change > 0) {
          static_cast<Monitor*>(self)->remember_writer(reader, status.last_publication_handle);
        }
      });
  measurement_reader_ = Entity(check_dds(
      dds_create_reader(subscriber_.get(), measurement_topic_.get(),
                        measurement_reader_qos().get(), listener),
      "dds_create_reader(measurement)"));
  model_reader_ = Entity(check_dds(
      dds_create_reader(subscriber_.get(), model_topic_.get(), model_qos().get(), listener),
      "dds_create_reader(model)"));
  dds_delete_listener(listener);
  residual_writer_ = make_writer(publisher_.get(), residual_topic_.get(), residual_qos(),
                                 "dds_create_writer(residual)");
  health_writer_ = make_writer(publisher_.get(), health_topic_.get(), health_writer_qos(),
                               "dds_create_writer(health)");
  waitset_ = Entity(check_dds(dds_create_waitset(participant), "dds_create_waitset"));
  for (dds_entity_t reader : {measurement_reader_.get(), model_reader_.get()}) {
    check_dds(dds_set_status_mask(reader, DDS_DATA_AVAILABLE_STATUS), "dds_set_status_mask");
    check_dds(dds_waitset_attach(waitset_.get(), reader, reader), "dds_waitset_attach");
  }
}

Monitor::~Monitor() {
  // No listener may run on members being destroyed (writer_partitions_ goes before the readers).
  for (dds_entity_t reader : {measurement_reader_.get(), model_reader_.get()}) {
    dds_set_listener(reader, nullptr);
  }
  // Gracefully gone: every cell's health disposed, so dashboards drop them at once.
  for (const auto& [test_cell, cell] : cells_) dispose_health(health_writer_.get(), test_cell);
}

void Monitor::stop() {
  stopping_ = true;
  dds_waitset_set_trigger(waitset_.get(), true);
}

void Monitor::run() {
  const auto period = std::chrono::duration_cast<Clock::duration>(
      std::chrono::duration<double>(options_.health_period_s));
  Clock::time_point next_health = Clock::now() + period;
  while (!stopping_) {
    const auto wait = std::max(Clock::duration::zero(), next_health - Clock::now());
    dds_waitset_wait(waitset_.get(), nullptr, 0,
                     std::chrono::duration_cast<std::chrono::nanoseconds>(wait).count());
    // Models first: a swap takes effect between two batches, never within one.
    take_models();
    take_measurements();
    if (Clock::now() >= next_health) {
      publish_health();
      next_health += period;
      if (next_health < Clock::now()) next_health = Clock::now() + period;
    }
  }
}

CellModel Monitor::model_for(const std::string& test_cell) {
  const auto configured = models_.find(test_cell);
  CellModel model = configured != models_.end() ? configured->second : default_model_;
  model.since = std::chrono::system_clock::now();
  return model;
}

Monitor::Cell* Monitor::cell(const std::string& test_cell) {
  auto found = cells_.find(test_cell);
  if (found == cells_.end()) {
    if (cells_.size() >= options_.max_cells && options_.cell_models.count(test_cell) == 0) {
      return nullptr;
    }
    spdlog::info("test cell {}: first sample, model {}", test_cell, model_for(test_cell).name);
    found = cells_.emplace(test_cell, std::make_unique<Cell>(Cell{
                                          CellMonitor(model_for(test_cell), options_.cell)}))
                .first;
    const auto refusal = model_refusals_.find(test_cell);
    if (refusal != model_refusals_.end()) {
      found->second->monitor.refuse_model(refusal->second);
      model_refusals_.erase(refusal);
    }
  }
  return found->second.get();
}

void Monitor::refuse_cell(const std::string& test_cell, std::size_t samples) {
  refused_batches_ += 1;
  refused_samples_ += samples;
  // Once, then a summary at most once a minute: a burst of names must not flood the log.
  const auto now = Clock::now();
  if (refused_batches_ == 1) {
    spdlog::warn("test cell {} refused: {} test cells are followed, the most --max-cells allows "
                 "(a place frees when a cell is disposed after --dispose-s without samples); "
                 "further refusals are summarised at most once a minute",
                 test_cell, options_.max_cells);
  } else if (now - refusals_logged_at_ >= std::chrono::minutes(1)) {
    spdlog::warn("{} measurement batches ({} samples) of test cells beyond --max-cells {} refused "
                 "so far, the latest of {}",
                 refused_batches_, refused_samples_, options_.max_cells, test_cell);
  } else {
    return;
  }
  refusals_logged_at_ = now;
}

void Monitor::remember_writer(dds_entity_t reader, dds_instance_handle_t publication) {
  std::vector<std::string> partitions = writer_partitions(reader, publication);
  if (partitions.empty()) return;  // gone already: its samples are refused
  std::lock_guard lock(writer_partitions_mutex_);
  if (writer_partitions_.size() >= 4096) writer_partitions_.clear();
  writer_partitions_[publication] = std::move(partitions);
}

bool Monitor::from_own_partition(dds_entity_t reader, dds_instance_handle_t publication,
                                 const std::string& test_cell, const char* what) {
  std::vector<std::string> partitions;
  {
    std::lock_guard lock(writer_partitions_mutex_);
    const auto found = writer_partitions_.find(publication);
    if (found != writer_partitions_.end()) partitions = found->second;
  }
  // Not learnt at its match (the map was emptied since): ask while it is still matched. A
  // writer already gone has no known partition, and its sample is refused.
  if (partitions.empty()) remember_writer(reader, publication);
  if (partitions.empty()) {
    std::lock_guard lock(writer_partitions_mutex_);
    const auto found = writer_partitions_.find(publication);
    if (found != writer_partitions_.end()) partitions = found->second;
  }
  if (partitions_speak_for(partitions, test_cell)) return true;
  std::string shown;
  for (const std::string& p : partitions) shown += (shown.empty() ? "" : ", ") + p;
  // The first 10, then every 1000th: a writer speaking for another cell must not flood the log.
  if (refused_foreign_++ < 10 || refused_foreign_ % 1000 == 0) {
    spdlog::warn("{} for test cell {} refused ({} so far): its writer publishes in partition(s) "
                 "[{}], not {}{} (a test cell's data comes only from its own partition)",
                 what, test_cell, refused_foreign_, shown, kCellPartitionPrefix, test_cell);
  }
  return false;
}

template <typename Map>
bool Monitor::make_room(Map& kept, const std::string& test_cell) {
  if (kept.count(test_cell) > 0 || options_.cell_models.count(test_cell) > 0) return true;
  if (kept.size() < 2 * options_.max_cells + options_.cell_models.size()) return true;
  // Full: what is kept for a test cell neither followed nor configured goes. There is always
  // one, since at most max_cells others are followed.
  for (auto it = kept.begin(); it != kept.end(); ++it) {
    if (cells_.count(it->first) == 0 && options_.cell_models.count(it->first) == 0) {
      if (dropped_swaps_++ == 0) {
        spdlog::warn("model swap kept for test cell {} (not seen yet) dropped for one of {}: "
                     "swaps are kept for at most {} test cells not followed; not logged again",
                     it->first, test_cell, options_.max_cells);
      }
      kept.erase(it);
      return true;
    }
  }
  return false;
}

CellModel Monitor::parsed_model(const std::string& text, const std::string& test_cell) {
  auto found = parsed_models_.find(text);
  if (found == parsed_models_.end()) {
    if (parsed_models_.size() >= kParsedModelsKept) parsed_models_.clear();
    found = parsed_models_
                .emplace(text, parse_cell_model(text, "model swap for " + test_cell, options_.catalog_dir))
                .first;
  }
  CellModel model = found->second;
  model.since = std::chrono::system_clock::now();
  return model;
}

void Monitor::take_models() {
  for (;;) {
    protocol::LoanedSamples<gearcoupling_ModelSwap, 16> swaps(model_reader_.get());
    if (swaps.size() == 0) return;
    for (std::size_t i = 0; i < swaps.size(); ++i) {
      if (!swaps.info(i).valid_data) continue;
      const gearcoupling_ModelSwap& swap = swaps[i];
      const std::string test_cell = swap.test_cell;
      try {
        require_test_cell_name(test_cell);
      } catch (const InvalidInput& error) {
        spdlog::warn("model swap refused: {}", error.what());
        continue;
      }
      if (!from_own_partition(model_reader_.get(), swaps.info(i).publication_handle, test_cell,
                              "model swap")) {
        continue;
      }
      if (!make_room(decimations_, test_cell) || !make_room(models_, test_cell) ||
          !make_room(model_refusals_, test_cell)) {
        continue;
      }
      if (swap.residual_decimation > 0) decimations_[test_cell] = swap.residual_decimation;
      const std::string text = swap.model_text != nullptr ? swap.model_text : "";
      if (text.empty()) continue;
      const auto existing = cells_.find(test_cell);
      try {
        CellModel model = parsed_model(text, test_cell);
        spdlog::info("test cell {}: model {} in force", test_cell, model.name);
        models_[test_cell] = model;
        model_refusals_.erase(test_cell);
        if (existing != cells_.end()) existing->second->monitor.swap_model(std::move(model));
      } catch (const ModelError& error) {
        spdlog::warn("test cell {}: model swap refused: {}", test_cell, error.what());
        if (existing != cells_.end()) {
          existing->second->monitor.refuse_model(error.what());
        } else {
          model_refusals_[test_cell] = error.what();   // told when the test cell appears
        }
      }
    }
  }
}

void Monitor::take_measurements() {
  for (;;) {
    protocol::LoanedSamples<gearcoupling_MeasurementBatch, 64> batches(measurement_reader_.get());
    if (batches.size() == 0) return;
    for (std::size_t i = 0; i < batches.size(); ++i) {
      if (!batches.info(i).valid_data) continue;
      const gearcoupling_MeasurementBatch& batch = batches[i];
      const std::string test_cell = batch.test_cell;
      try {
        require_test_cell_name(test_cell);
      } catch (const InvalidInput& error) {
        spdlog::warn("measurement batch of {} samples refused: {}", batch.samples._length,
                     error.what());
        continue;
      }
      if (!from_own_partition(measurement_reader_.get(), batches.info(i).publication_handle,
                              test_cell, "measurement batch")) {
        continue;
      }
      Cell* followed = cell(test_cell);
      if (followed == nullptr) {
        refuse_cell(test_cell, batch.samples._length);
        continue;
      }
      Cell& c = *followed;
      c.last_sample = Clock::now();
      const auto decimation = decimations_.find(test_cell);
      const std::uint32_t every = decimation != decimations_.end() ? decimation->second
                                                                   : options_.decimation;
      c.residuals.clear();
      for (std::uint32_t k = 0; k < batch.samples._length; ++k) {
        const gearcoupling_Measurement& m = batch.samples._buffer[k];
        std::optional<RecordedSample> sample;
        std::string refusal;
        try {
          sample = from_wire(m);
        } catch (const InvalidInput& error) {
          refusal = error.field() + ": " + error.what();
        }
        SensorMoments predicted;
        if (c.monitor.take(batch.run_id, m.sequence_number, sample, refusal, predicted) !=
            SampleOutcome::evaluated) {
          continue;
        }
        if (c.decimation_count++ % every != 0) continue;
        c.residuals.push_back({m.sequence_number, m.time_s, m.msy_nm, m.msz_nm, predicted.y_nm,
                               predicted.z_nm});
      }
      if (c.residuals.empty()) continue;
      gearcoupling_ResidualBatch out{};
      std::copy_n(test_cell.c_str(), test_cell.size() + 1, out.test_cell);
      out.run_id = batch.run_id;
      out.model_name = const_cast<char*>(c.monitor.model().name.c_str());
      out.decimation = every;
      out.published_ns = realtime_ns();
      out.residuals._buffer = c.residuals.data();
      out.residuals._length = out.residuals._maximum = static_cast<std::uint32_t>(c.residuals.size());
      out.residuals._release = false;
      dds_write(residual_writer_.get(), &out);
    }
  }
}

void Monitor::publish_health() {
  const auto now = Clock::now();
  const auto wall = std::chrono::system_clock::now();
  for (auto it = cells_.begin(); it != cells_.end();) {
    const double silent_s = std::chrono::duration<double>(now - it->second->last_sample).count();
    if (silent_s >= options_.dispose_s) {
      spdlog::info("test cell {}: nothing for {:.1f} s, health disposed", it->first, silent_s);
      dispose_health(health_writer_.get(), it->first);
      it = cells_.erase(it);
      continue;
    }
    write_health(health_writer_.get(), it->first, monitor_id_, silent_s >= options_.stale_s,
                 it->second->monitor.health(wall));
    ++it;
  }
}

}  // namespace gc::live
