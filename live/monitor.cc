#include "live/monitor.h"

#include <fmt/format.h>
#include <spdlog/spdlog.h>

#include <vector>

#include "core/model_error.h"
#include "gearcoupling.h"
#include "live/health_wire.h"
#include "live/proposal_wire.h"
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
  std::uint64_t generation = 0;
  Clock::time_point last_sample = Clock::now();
  std::uint64_t decimation_count = 0;
  std::vector<gearcoupling_Residual> residuals = {};
  // The learning loop: since when the error is beyond the noise (under this model, this run),
  // the latest diagnosis and recheck submitted, and the latest proposal published.
  std::optional<Clock::time_point> systematic_since = std::nullopt;
  std::optional<Clock::time_point> diagnosed_at = std::nullopt, rechecked_at = std::nullopt;
  std::optional<Clock::time_point> onset_of_diagnosis = std::nullopt;
  std::optional<Proposal> proposal = std::nullopt;
  std::uint64_t evaluated_at_proposal = 0;
  // What the learning status says (live/learning_status.h): the latest diagnosis' note when it
  // found nothing, whether the queue refused the latest one, the state last logged.
  std::optional<std::string> found_nothing = std::nullopt;
  bool queue_full = false;
  std::string logged_learning_state = {};
};

namespace {

Entity make_writer(dds_entity_t publisher, dds_entity_t topic, const protocol::Qos& qos,
                   const char* what) {
  return Entity(check_dds(dds_create_writer(publisher, topic, qos.get(), nullptr), what));
}

double seconds_between(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

/// Rows a diagnosis needs at least (diagnose refuses fewer: 4 * folds * blocks per fold).
std::size_t min_diagnosis_samples() {
  const CrossValidationSettings cv = DiagnosisSettings{}.cross_validation;
  return 4 * static_cast<std::size_t>(cv.folds) * static_cast<std::size_t>(cv.blocks_per_fold);
}

/// What the audit trail keeps of a swap writer's claims (by=, source=) [bytes].
constexpr std::size_t kMaxClaimBytes = 128;

std::string hex16(std::uint64_t value) { return fmt::format("{:016x}", value); }

/// The value of `key` in a swap writer's USER_DATA "by=...;source=...", "" when absent.
std::string user_data_value(const std::string& user_data, const std::string& key) {
  std::size_t at = 0;
  while (at < user_data.size()) {
    const std::size_t end = std::min(user_data.find(';', at), user_data.size());
    const std::string item = user_data.substr(at, end - at);
    if (item.rfind(key + "=", 0) == 0) return item.substr(key.size() + 1);
    at = end + 1;
  }
  return "";
}

}  // namespace

SwapOrigin swap_origin(dds_entity_t reader, dds_instance_handle_t publication) {
  const WriterInfo info = writer_info(reader, publication);
  SwapOrigin origin{user_data_value(info.user_data, "by"), user_data_value(info.user_data, "source"),
                    info.writer, ""};
  if (origin.by.empty()) origin.by = info.participant.empty() ? "unknown" : "participant " + info.participant;
  // The writer's own claims, of any length and bytes: bounded and printable in the trail.
  origin.by = printable(origin.by, kMaxClaimBytes);
  origin.source = printable(origin.source, kMaxClaimBytes);
  return origin;
}

namespace {

std::uint64_t realtime_ns() {
  return static_cast<std::uint64_t>(std::chrono::duration_cast<std::chrono::nanoseconds>(
                                        std::chrono::system_clock::now().time_since_epoch())
                                        .count());
}

}  // namespace

Monitor::Monitor(const MonitorOptions& options)
    : options_(options),
      monitor_id_(protocol::random_id()),
      audit_(options.state_dir),
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
  proposal_topic_ = make_proposal_topic(participant);
  monitor_topic_ = make_monitor_status_topic(participant);
  proposal_writer_ = make_writer(publisher_.get(), proposal_topic_.get(), proposal_qos(),
                                 "dds_create_writer(proposal)");
  monitor_writer_ = make_writer(publisher_.get(), monitor_topic_.get(), monitor_status_qos(),
                                "dds_create_writer(monitor status)");
  waitset_ = Entity(check_dds(dds_create_waitset(participant), "dds_create_waitset"));
  for (dds_entity_t reader : {measurement_reader_.get(), model_reader_.get()}) {
    check_dds(dds_set_status_mask(reader, DDS_DATA_AVAILABLE_STATUS), "dds_set_status_mask");
    check_dds(dds_waitset_attach(waitset_.get(), reader, reader), "dds_waitset_attach");
  }
  outcomes_ready_ = Entity(check_dds(dds_create_guardcondition(participant), "dds_create_guardcondition"));
  check_dds(dds_waitset_attach(waitset_.get(), outcomes_ready_.get(), outcomes_ready_.get()),
            "dds_waitset_attach(guard)");
  if (options_.learning.enabled) {
    const dds_entity_t guard = outcomes_ready_.get();
    worker_ = std::make_unique<DiagnosisWorker>(options_.learning.queue, options_.learning.nice,
                                                options_.learning.cpu_share, [guard] { dds_set_guardcondition(guard, true); });
  }
}

Monitor::~Monitor() {
  // No listener may run on members being destroyed (writer_partitions_ goes before the readers).
  for (dds_entity_t reader : {measurement_reader_.get(), model_reader_.get()}) {
    dds_set_listener(reader, nullptr);
  }
  worker_.reset();   // waits for a diagnosis running
  // Gracefully gone: every cell's health and proposal disposed, so dashboards drop them at once.
  for (const auto& [test_cell, cell] : cells_) {
    dispose_health(health_writer_.get(), test_cell);
    if (cell->proposal) dispose_proposal(proposal_writer_.get(), test_cell);
  }
  dispose_monitor_status(monitor_writer_.get(), monitor_id_);
  audit_.close();
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
    take_outcomes();
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
                                          CellMonitor(model_for(test_cell), options_.cell),
                                          next_generation_++}))
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
  refusals_.refuse(Refusal::batch_beyond_max_cells,
                   fmt::format("measurement batch of test cell {} refused: {} test cells are "
                               "followed, the most --max-cells allows (a place frees when a cell "
                               "is disposed after --dispose-s without samples)",
                               test_cell, options_.max_cells),
                   samples);
}

void Monitor::remember_writer(dds_entity_t reader, dds_instance_handle_t publication) {
  std::vector<std::string> partitions = writer_partitions(reader, publication);
  if (partitions.empty()) return;  // gone already: its samples are refused
  std::lock_guard lock(writer_partitions_mutex_);
  if (writer_partitions_.size() >= 4096) writer_partitions_.clear();
  writer_partitions_[publication] = std::move(partitions);
}

std::vector<std::string> Monitor::partitions_of(dds_entity_t reader, dds_instance_handle_t publication) {
  std::vector<std::string> partitions;
  {
    std::lock_guard lock(writer_partitions_mutex_);
    const auto found = writer_partitions_.find(publication);
    if (found != writer_partitions_.end()) partitions = found->second;
  }
  // Not learnt at its match (the map was emptied since): ask while it is still matched. A
  // writer already gone has no known partition.
  if (partitions.empty()) remember_writer(reader, publication);
  if (partitions.empty()) {
    std::lock_guard lock(writer_partitions_mutex_);
    const auto found = writer_partitions_.find(publication);
    if (found != writer_partitions_.end()) partitions = found->second;
  }
  return partitions;
}

bool Monitor::from_own_partition(dds_entity_t reader, dds_instance_handle_t publication,
                                 const std::string& test_cell, Refusal kind, const char* what) {
  const std::vector<std::string> partitions = partitions_of(reader, publication);
  if (partitions_speak_for(partitions, test_cell)) return true;
  std::string shown;
  for (const std::string& p : partitions) shown += (shown.empty() ? "" : ", ") + p;
  refusals_.refuse(kind, fmt::format("{} for test cell {} refused: its writer publishes in "
                                     "partition(s) [{}], not {}{} (a test cell's data comes only "
                                     "from its own partition)",
                                     what, test_cell, shown, kCellPartitionPrefix, test_cell));
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
        refusals_.refuse(Refusal::swap_bad_name, std::string("model swap refused: ") + error.what());
        continue;
      }
      if (!from_own_partition(model_reader_.get(), swaps.info(i).publication_handle, test_cell,
                              Refusal::swap_foreign, "model swap")) {
        continue;
      }
      if (!make_room(decimations_, test_cell) || !make_room(models_, test_cell) ||
          !make_room(model_refusals_, test_cell)) {
        refusals_.refuse(Refusal::swap_no_room,
                         "model swap for test cell " + test_cell + " refused: no room to keep it");
        continue;
      }
      if (swap.residual_decimation > 0) decimations_[test_cell] = swap.residual_decimation;
      const std::string text = swap.model_text != nullptr ? swap.model_text : "";
      if (text.empty()) continue;
      const auto existing = cells_.find(test_cell);
      try {
        CellModel model = parsed_model(text, test_cell);
        SwapOrigin origin = swap_origin(model_reader_.get(), swaps.info(i).publication_handle);
        origin.operator_identity = operator_identity_of(
            partitions_of(model_reader_.get(), swaps.info(i).publication_handle));
        const std::int64_t written_ns = swaps.info(i).source_timestamp;
        spdlog::info("test cell {}: model {} in force (by {})", test_cell, model.name, origin.by);
        models_[test_cell] = model;
        model_refusals_.erase(test_cell);
        Cell* cell = existing != cells_.end() ? existing->second.get() : nullptr;
        // A restarted monitor is given every live swap writer's latest swap again
        // (TRANSIENT_LOCAL): in force again, but not a new swap of the trail.
        if (audit_.contains(origin.writer, written_ns)) {
          spdlog::info("test cell {}: swap to {} by {} already in the audit trail", test_cell,
                       model.name, origin.by);
        } else {
          audit_swap(test_cell, cell, model, text, origin, written_ns);
        }
        if (cell != nullptr) cell->monitor.swap_model(std::move(model));
      } catch (const std::exception& error) {
        // Whatever the text did (a ModelError, or worse: memory), the model in force stays and
        // the monitor serves on; a restart into the same swap refuses it the same way.
        refuse_model(test_cell, error);
      }
    }
  }
}

void Monitor::refuse_model(const std::string& test_cell, const std::exception& error) {
  const bool model_error = dynamic_cast<const ModelError*>(&error) != nullptr;
  // Bounded and printable: it is shown on every dashboard (CellHealth.last_model_refusal).
  const std::string reason =
      printable(model_error ? error.what() : std::string("model swap for ") + test_cell +
                                                 ": could not be loaded (" + error.what() + ")",
                kMaxRefusalBytes);
  refusals_.refuse(Refusal::swap_bad_model, "test cell " + test_cell + ": model swap refused: " + reason);
  const auto existing = cells_.find(test_cell);
  if (existing != cells_.end()) {
    existing->second->monitor.refuse_model(reason);
  } else {
    model_refusals_[test_cell] = reason;   // told when the test cell appears
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
        refusals_.refuse(Refusal::batch_bad_name,
                         fmt::format("measurement batch of {} samples refused: {}",
                                     batch.samples._length, error.what()),
                         batch.samples._length);
        continue;
      }
      if (batch.samples._length > kMaxBatchSamples) {
        refusals_.refuse(Refusal::batch_oversized,
                         fmt::format("measurement batch for test cell {} refused: {} samples, "
                                     "allowed 0 to {} a batch",
                                     test_cell, batch.samples._length, kMaxBatchSamples),
                         batch.samples._length);
        continue;
      }
      if (!from_own_partition(measurement_reader_.get(), batches.info(i).publication_handle,
                              test_cell, Refusal::batch_foreign, "measurement batch")) {
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
      c.monitor.end_batch();
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
      if (it->second->proposal) dispose_proposal(proposal_writer_.get(), it->first);
      audit_.freeze(it->first);
      it = cells_.erase(it);
      continue;
    }
    HealthReport health = it->second->monitor.health(wall);
    const bool stale = silent_s >= options_.stale_s;
    if (health.unit_slip) {
      health.unit_error = analysis::unit_slip_error("test cell " + it->first, *health.unit_slip,
                                                    analysis::UnitFix::stream);
    }
    if (worker_) learn(it->first, *it->second, health, stale);
    health.learning = learning_of(it->first, *it->second, health, stale);
    write_health(health_writer_.get(), it->first, monitor_id_, stale, health);
    audit_.follow(it->first, health, now);
    ++it;
  }
  refusals_.flush();
  write_monitor_status(monitor_writer_.get(), monitor_id_, counters(), audit_);
}

MonitorCounters Monitor::counters() const {
  MonitorCounters c{cells_.size(), options_.max_cells, refused_batches(),
                    refusals_.samples(Refusal::batch_beyond_max_cells), refused_foreign(),
                    proposals_published_, proposals_withdrawn_, diagnoses_run_, diagnoses_dropped_,
                    worker_ ? worker_->running() : std::string(), {}};
  for (std::size_t k = 0; k < kRefusalKinds; ++k) c.refusals[k] = refusals_.count(static_cast<Refusal>(k));
  return c;
}

void Monitor::learn(const std::string& test_cell, Cell& cell, const HealthReport& health,
                    bool stale) {
  const auto now = Clock::now();
  const LearningOptions& o = options_.learning;
  const std::size_t needed = min_diagnosis_samples();
  // Judged on a sample count, not on the diagnosis' 400: a 10 s window at 50 Hz holds 250-500,
  // and wanting 400 there reset the clock every other window (issue 39).
  // Moments 1000 times off are a unit error, not something a model lacks.
  const bool systematic = !health.unit_slip && health.window_samples >= kSamplesToJudge &&
                          (!health.model.channels[0].at_noise_level ||
                           !health.model.channels[1].at_noise_level);
  if (!systematic) {
    cell.systematic_since.reset();
  } else if (!cell.systematic_since) {
    cell.systematic_since = now;
  }
  cell.queue_full = false;
  const SampleWindow& window = cell.monitor.recent_samples();
  if (stale || window.size() < needed || worker_->busy(test_cell)) return;
  auto due = [&](const std::optional<Clock::time_point>& last, double period_s) {
    return !last || seconds_between(*last, now) >= period_s;
  };
  DiagnosisJob job{test_cell, cell.generation, cell.monitor.model(), {}, std::nullopt};
  if (cell.proposal && cell.proposal->state == ProposalState::standing &&
      health.counts.evaluated - cell.evaluated_at_proposal >= needed &&
      due(cell.rechecked_at ? cell.rechecked_at : cell.diagnosed_at, o.recheck_s)) {
    job.recheck = cell.proposal;
  } else if (cell.systematic_since && seconds_between(*cell.systematic_since, now) >= o.diagnose_after_s &&
             due(cell.diagnosed_at, o.rediagnose_s)) {
  } else {
    return;
  }
  job.samples = window.samples();
  const bool recheck = job.recheck.has_value();
  if (!worker_->submit(std::move(job))) {
    ++diagnoses_dropped_;
    cell.queue_full = !recheck;
    spdlog::debug("test cell {}: diagnosis queue full, {} dropped", test_cell,
                  recheck ? "recheck" : "diagnosis");
    return;
  }
  // Marked only once submitted: a job the full queue refused is tried again next period.
  if (recheck) {
    cell.rechecked_at = now;
  } else {
    cell.diagnosed_at = now;
    cell.onset_of_diagnosis = cell.systematic_since;
  }
  spdlog::info("test cell {}: {} on {} samples", test_cell,
               recheck ? "rechecking proposal " + hex16(cell.proposal->id)
                       : "error beyond the noise for " +
                             fmt::format("{:.1f} s, diagnosing", seconds_between(*cell.systematic_since, now)),
               window.size());
}

LearningStatus Monitor::learning_of(const std::string& test_cell, Cell& cell,
                                    const HealthReport& health, bool stale) {
  const auto now = Clock::now();
  const LearningOptions& o = options_.learning;
  LearningInputs in;
  in.enabled = worker_ != nullptr;
  in.stale = stale;
  in.sample_rate_hz = health.sample_rate_hz;
  in.window_s = options_.cell.window_s;
  in.window_samples = health.window_samples;
  in.beyond_noise = cell.systematic_since.has_value();
  if (cell.systematic_since) in.beyond_noise_for_s = seconds_between(*cell.systematic_since, now);
  in.diagnose_after_s = o.diagnose_after_s;
  in.rolling_samples = cell.monitor.recent_samples().size();
  in.samples_needed = min_diagnosis_samples();
  if (worker_ && worker_->busy(test_cell)) {
    (worker_->running() == test_cell ? in.diagnosis_running : in.diagnosis_queued) = true;
  }
  in.queue_full = cell.queue_full;
  if (cell.proposal && cell.proposal->state == ProposalState::standing) {
    in.standing_proposal = hex16(cell.proposal->id);
  }
  // Its first line: the diagnosis' summary runs to a paragraph.
  if (cell.found_nothing) in.found_nothing = cell.found_nothing->substr(0, cell.found_nothing->find('\n'));
  if (cell.diagnosed_at) {
    in.next_diagnosis_in_s = o.rediagnose_s - seconds_between(*cell.diagnosed_at, now);
  }
  LearningStatus status = learning_status(in);
  if (health.unit_slip && !in.diagnosis_running && !in.diagnosis_queued) {
    status = {"unit_error", health.unit_error, 0};
  }
  // One log line per change of state: a cell far off and not diagnosed says why (issue 39).
  if (status.state != cell.logged_learning_state) {
    spdlog::info("test cell {}: learning: {}", test_cell, status.text);
    cell.logged_learning_state = status.state;
  }
  return status;
}

void Monitor::take_outcomes() {
  if (!worker_) return;
  bool triggered = false;
  dds_take_guardcondition(outcomes_ready_.get(), &triggered);
  for (DiagnosisOutcome& outcome : worker_->take_outcomes()) take_outcome(std::move(outcome));
}

void Monitor::take_outcome(DiagnosisOutcome outcome) {
  ++diagnoses_run_;
  const auto found = cells_.find(outcome.test_cell);
  // A cell gone (or gone and back) while it was diagnosed gets nothing; nor does a cell whose
  // model was swapped meanwhile: what was found is about a model no longer in force.
  if (found == cells_.end() || found->second->generation != outcome.cell_generation) {
    spdlog::info("test cell {}: gone during its diagnosis; nothing proposed", outcome.test_cell);
    return;
  }
  Cell& cell = *found->second;
  if (cell.monitor.model().model != outcome.base.model) {
    spdlog::info("test cell {}: model swapped during its diagnosis; nothing proposed",
                 outcome.test_cell);
    return;
  }
  if (outcome.rechecked) {
    if (!cell.proposal || cell.proposal->id != outcome.rechecked->id ||
        cell.proposal->state != ProposalState::standing) {
      return;
    }
    if (!outcome.base_rmse_nm || !outcome.proposed_rmse_nm) return;
    spdlog::info("test cell {}: proposal {} rechecked: RMSE {:.0f} N·m with it, {:.0f} without",
                 outcome.test_cell, hex16(cell.proposal->id), *outcome.proposed_rmse_nm,
                 *outcome.base_rmse_nm);
    if (*outcome.proposed_rmse_nm < *outcome.base_rmse_nm) return;
    cell.proposal->state = ProposalState::withdrawn;
    cell.proposal->state_reason = fmt::format(
        "contradicted by later data: on the latest {} samples its RMSE {:.0f} N·m is not below "
        "the model's {:.0f} N·m", outcome.samples,
        *outcome.proposed_rmse_nm, *outcome.base_rmse_nm);
    ++proposals_withdrawn_;
    publish_proposal(cell);
    return;
  }
  cell.found_nothing.reset();
  if (!outcome.proposal) {
    cell.found_nothing = outcome.note;
    spdlog::info("test cell {}: diagnosis proposes nothing ({:.1f} s CPU): {}", outcome.test_cell,
                 outcome.cpu_s, outcome.note);
    return;
  }
  Proposal& p = *outcome.proposal;
  p.id = protocol::random_id();
  p.proposed_at = std::chrono::system_clock::now();
  p.diagnosis_cpu_s = outcome.cpu_s;
  if (cell.onset_of_diagnosis) p.onset_to_proposal_s = seconds_between(*cell.onset_of_diagnosis, Clock::now());
  if (cell.proposal && !replaces(p, *cell.proposal)) {
    spdlog::info("test cell {}: diagnosis found {} ({:.0f} % less error), not better than proposal "
                 "{} ({:.0f} %)", outcome.test_cell, p.effects, 100.0 * p.reduction(),
                 hex16(cell.proposal->id), 100.0 * cell.proposal->reduction());
    return;
  }
  spdlog::info("test cell {}: proposal {}: {} ({}), held-out RMSE {:.0f} -> {:.0f} N·m, {:.1f} s CPU",
               outcome.test_cell, hex16(p.id), p.effects, p.kind, p.before_rmse_nm,
               p.after_rmse_nm, p.diagnosis_cpu_s);
  cell.proposal = std::move(p);
  cell.evaluated_at_proposal = cell.monitor.health(std::chrono::system_clock::now()).counts.evaluated;
  cell.rechecked_at.reset();
  publish_proposal(cell);
}

void Monitor::publish_proposal(Cell& cell) {
  if (cell.proposal->state == ProposalState::standing) ++proposals_published_;
  // While it stands, its model also follows the health window: "now" and "with it" on one window.
  cell.monitor.shadow(cell.proposal->state == ProposalState::standing ? cell.proposal->model : nullptr);
  write_proposal(proposal_writer_.get(), monitor_id_, *cell.proposal);
}

void Monitor::audit_swap(const std::string& test_cell, Cell* cell, const CellModel& model,
                         const std::string& text, const SwapOrigin& origin, std::int64_t written_ns) {
  SwapEntry entry;
  entry.id = protocol::random_id();
  entry.writer = origin.writer;
  entry.written_ns = written_ns;
  entry.test_cell = test_cell;
  entry.at = std::chrono::system_clock::now();
  entry.by = origin.by;
  entry.operator_identity = origin.operator_identity;
  entry.source = origin.source.empty() ? "model text" : origin.source;
  entry.model_after = model.name;
  bool proposal_changed = false;
  if (cell != nullptr) {
    const HealthReport before = cell->monitor.health(entry.at);
    entry.model_before = before.model.model_name;
    for (std::size_t c = 0; c < 2; ++c) entry.before_rmse_nm[c] = before.model.channels[c].rmse_nm;
    cell->systematic_since.reset();
    std::optional<Proposal>& p = cell->proposal;
    proposal_changed = p && p->state == ProposalState::standing;
    if (proposal_changed) {
      if (p->model_text == text) {
        p->state = ProposalState::applied;
        p->state_reason = "applied by " + origin.by +
                          (origin.operator_identity.empty() ? "" : " (" + origin.operator_identity + ")");
        entry.proposal_id = p->id;
        entry.source = "proposal " + hex16(p->id);
      } else {
        p->state = ProposalState::withdrawn;
        p->state_reason = "its base model " + p->base_model + " was replaced by " + model.name;
        ++proposals_withdrawn_;
      }
    }
  }
  spdlog::info("test cell {}: swap {} -> {} by {}{} from {}", test_cell, entry.model_before,
               entry.model_after, entry.by,
               entry.operator_identity.empty() ? "" : " (identity " + entry.operator_identity + ")",
               entry.source);
  audit_.add(std::move(entry));   // on disk before anyone sees the proposal applied
  if (proposal_changed) publish_proposal(*cell);
}

}  // namespace gc::live
