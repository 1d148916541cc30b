#include "service/service.h"

#include <thread>

#include <spdlog/spdlog.h>

#include "protocol/calculation_traits.h"
#include "protocol/matching.h"
#include "protocol/names.h"
#include "protocol/qos.h"
#include "protocol/random_id.h"
#include "protocol/reply_status.h"
#include "protocol/samples.h"
#include "protocol/topics.h"
#include "protocol/wire_inputs.h"
#include "protocol/wire_requests.h"
#include "protocol/wire_results.h"
#include "service/batch.h"
#include "service/compute.h"
#include "service/inline_answer.h"
#include "service/periodic_work.h"

namespace gc::service {

using protocol::Calculation;
using protocol::CalculationTraits;
using protocol::check_dds;
using protocol::Entity;
using Clock = std::chrono::steady_clock;

namespace {

/// Requests waiting for their client's reply reader, at most: a flood of made-up client ids
/// costs a bounded amount of memory and then one admission check per request.
constexpr std::size_t kMaxParkedRequests = 1024;
/// Replies waiting for clients that do not acknowledge, at most, and for one client: eight
/// deaf clients fill it before another's replies find no room.
constexpr std::size_t kMaxBackloggedReplies = 4096;
constexpr std::size_t kMaxBackloggedRepliesPerClient = 512;
/// How often the dispatch loop looks at parked requests while there are some (and at reply
/// writers while they move to a new reply domain).
constexpr std::chrono::milliseconds kParkedPoll{10};
/// A client that left is remembered this long: its late requests are dropped (ReplyWriters).
constexpr double kDepartedMemoryS = 60.0;
/// A reply writer that moved to a new reply domain is deleted this long after a reply may last
/// have been handed to the ReplyBacklog with it (reply_block_s): no reply is lost to the move.
constexpr double kMovedWriterLingerS = 1.0;

unsigned worker_count(unsigned configured) {
  if (configured > 0) return configured;
  return std::max(1u, std::thread::hardware_concurrency());
}

Clock::duration seconds(double s) {
  return std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(s));
}

protocol::DeadlineExceeded deadline_exceeded(Calculation calculation, double deadline_s,
                                             Clock::time_point received, const char* where) {
  const double elapsed_s = std::chrono::duration<double>(Clock::now() - received).count();
  return protocol::DeadlineExceeded(fmt::format(
      "{} not answered within the service's deadline of {} s per calculation "
      "(calculation_deadline_s): stopped {} after {:.3g} s; the instance is overloaded or the "
      "request too costly, retry later or elsewhere",
      protocol::to_string(calculation), deadline_s, where, elapsed_s));
}

// Runs `run(cancelled)` unless the request has already spent its time in the queue, with a
// predicate the core's iterations ask (LoadSharingOptions::cancelled). So no request holds a
// worker, or the drain at shutdown, past received + deadline_s, and the core knows no clock.
template <typename Run>
auto within_deadline(Calculation calculation, double deadline_s, Clock::time_point received,
                     Run run) {
  const Clock::time_point deadline = received + seconds(deadline_s);
  if (Clock::now() >= deadline) {
    throw deadline_exceeded(calculation, deadline_s, received, "in the queue");
  }
  try {
    return run(CancelPredicate([deadline] { return Clock::now() >= deadline; }));
  } catch (const Cancelled&) {
    throw deadline_exceeded(calculation, deadline_s, received, "while computing");
  }
}

// One line per batch with failed cases, naming the first: a batch of 4096 bad cases must not
// write 4096 lines.
void log_failed_cases(const gearcoupling_Correlation& correlation,
                      const protocol::BatchResult& result) {
  std::size_t failed = 0;
  const protocol::BatchCaseReply* first = nullptr;
  for (const protocol::BatchCaseReply& c : result.cases) {
    if (c.status == protocol::kCaseOk) continue;
    if (failed++ == 0) first = &c;
  }
  if (failed == 0) return;
  spdlog::warn("batch client={} seq={}: {} of {} cases failed, the first: {} field=\"{}\": {}",
               protocol::hex_id(correlation.client_id), correlation.sequence_number, failed,
               result.cases.size(),
               protocol::to_string(static_cast<gearcoupling_ReplyStatus>(first->status)),
               first->field, first->message);
}

}  // namespace

Service::Service(const ServiceConfig& config, Catalogue catalogue, const protocol::DdsConfig& dds)
    : config_(config),
      catalogue_(std::move(catalogue)),
      instance_id_(protocol::random_id()),
      participant_(protocol::create_participant(config.domain, dds)),
      request_topics_(protocol::make_request_topics(participant_.get())),
      reply_writers_([domain = config.domain, dds] { return std::make_unique<ReplyDomain>(domain, dds); },
                     protocol::hex_id(instance_id_), kMaxParkedRequests,
                     [this] { dds_set_guardcondition(guard_.get(), true); }, kDepartedMemoryS,
                     ReplyWriters::kWritersPerDomain, config.reply_block_s + kMovedWriterLingerS),
      reply_backlog_(config.reply_block_s, kMaxBackloggedReplies, kMaxBackloggedRepliesPerClient,
                     [this](std::uint64_t client_id) {
                       reply_writers_.mark_departed(client_id, config_.departed_hold_s);
                     }),
      status_(participant_.get(), instance_id_, worker_count(config.threads),
              config.liveliness_lease_s, catalogue_, stats_),
      pool_(worker_count(config.threads)) {
  if (dds.source == protocol::DdsConfigSource::kInstalled) {
    domain_ = Entity(check_dds(dds_get_parent(participant_.get()), "dds_get_parent(participant)"));
  }
  const protocol::Qos partition = protocol::partition_qos(protocol::request_partition(instance_id_));
  request_subscriber_ = Entity(check_dds(
      dds_create_subscriber(participant_.get(), partition.get(), nullptr), "dds_create_subscriber"));
  waitset_ = Entity(check_dds(dds_create_waitset(participant_.get()), "dds_create_waitset"));
  // Before the request readers: parking a request sets it to wake the dispatch loop.
  guard_ = Entity(check_dds(dds_create_guardcondition(participant_.get()),
                            "dds_create_guardcondition"));
  check_dds(dds_waitset_attach(waitset_.get(), guard_.get(), 0), "dds_waitset_attach");
  // Requests are taken in Cyclone's delivery thread (a data-available listener), not by a
  // thread woken through a waitset: one thread hop less on every round trip.
  const protocol::Qos qos = protocol::request_reply_qos();
  protocol::for_each_calculation([&](auto calculation) {
    constexpr Calculation kCalculation = decltype(calculation)::value;
    dds_listener_t* listener = dds_create_listener(this);
    dds_lset_data_available(listener, [](dds_entity_t, void* service) {
      static_cast<Service*>(service)->take_requests<kCalculation>();
    });
    const std::size_t i = protocol::index_of(kCalculation);
    request_readers_[i] = Entity(check_dds(
        dds_create_reader(request_subscriber_.get(), request_topics_[i].get(), qos.get(), listener),
        "dds_create_reader(request)"));
    dds_delete_listener(listener);
  });
  subscriptions_reader_ = Entity(check_dds(
      dds_create_reader(participant_.get(), DDS_BUILTIN_TOPIC_DCPSSUBSCRIPTION, nullptr, nullptr),
      "dds_create_reader(DCPSSubscription)"));
  dds_set_status_mask(subscriptions_reader_.get(), DDS_DATA_AVAILABLE_STATUS);
  check_dds(dds_waitset_attach(waitset_.get(), subscriptions_reader_.get(), 0),
            "dds_waitset_attach");
}

Service::~Service() { pool_.drain_and_stop(); }

void Service::request_stop() {
  stop_requested_ = true;
  dds_set_guardcondition(guard_.get(), true);
}

void Service::request_reload() {
  reload_requested_ = true;
  request_stop();
}

template <Calculation kCalculation>
void Service::take_requests() {
  using T = CalculationTraits<kCalculation>;
  const dds_entity_t reader = request_readers_[protocol::index_of(kCalculation)].get();
  for (;;) {
    protocol::LoanedSamples<typename T::WireRequest> samples(reader);
    if (samples.size() == 0) return;
    const Clock::time_point received = Clock::now();
    struct Job {
      gearcoupling_Correlation correlation;
      std::optional<dds_guid_t> requester;
      std::function<void()> run;
      bool cheap;  ///< cheap_to_answer, or malformed (answered with an error at once)
    };
    std::vector<Job> jobs;
    jobs.reserve(samples.size());
    for (std::size_t i = 0; i < samples.size(); ++i) {
      if (!samples.info(i).valid_data) continue;
      const gearcoupling_Correlation correlation = samples[i].correlation;
      // Who wrote it, found now while its writer is surely still matched: the reply goes only
      // to this participant (answer()).
      const std::optional<dds_guid_t> requester =
          requesters_.participant_of(reader, samples.info(i).publication_handle);
      std::optional<typename T::Request> request;
      std::exception_ptr malformed;
      try {
        request = protocol::from_wire(samples[i]);
      } catch (...) {
        malformed = std::current_exception();
      }
      const bool cheap = !request || cheap_to_answer(*request, catalogue_);
      jobs.push_back({correlation, requester,
                      [this, correlation, requester, request = std::move(request), malformed,
                       received] {
                        answer<kCalculation>(correlation, requester, request, malformed, received);
                      },
                      cheap});
    }
    // A lone cheap request is answered here, in Cyclone's receive thread (inline_answer.h); a
    // costly one, or a burst, goes to the workers, so that no request holds up the others.
    const bool lone = jobs.size() == 1;
    for (Job& job : jobs) {
      admit(kCalculation, job.correlation, job.requester, std::move(job.run), lone && job.cheap);
    }
  }
}

template <Calculation kCalculation>
void Service::answer(const gearcoupling_Correlation& correlation,
                     const std::optional<dds_guid_t>& requester,
                     const std::optional<typename CalculationTraits<kCalculation>::Request>& request,
                     std::exception_ptr malformed, Clock::time_point received) {
  using T = CalculationTraits<kCalculation>;
  // Admitted only once the client's reply writer matched (admit()): before any computing, the
  // reply must reach the participant that wrote the request, or the client_id was forged.
  const dds_entity_t writer = reply_writers_.writer(correlation.client_id, kCalculation);
  if (writer != 0 && (!requester || !requesters_.reaches(writer, *requester))) {
    refuse_forged(kCalculation, correlation);
    return;
  }
  auto sample = std::make_shared<protocol::OwnedSample<typename T::WireReply>>(T::reply_type());
  typename T::WireReply& reply = sample->get();
  reply.correlation = correlation;
  try {
    if (malformed) std::rethrow_exception(malformed);
    const typename T::Result result =
        within_deadline(kCalculation, config_.calculation_deadline_s, received,
                        [&](const CancelPredicate& cancelled) {
                          if constexpr (kCalculation == Calculation::kBatch) {
                            return compute_batch(catalogue_, *request, cancelled, [&] {
                              return std::make_exception_ptr(deadline_exceeded(
                                  kCalculation, config_.calculation_deadline_s, received,
                                  "while computing"));
                            });
                          } else {
                            return compute_request(catalogue_, *request, cancelled);
                          }
                        });
    if constexpr (kCalculation == Calculation::kBatch) log_failed_cases(correlation, result);
    protocol::to_wire(result, reply.result);
    reply.status = gearcoupling_STATUS_OK;
    reply.field = protocol::wire_string("");
    reply.message = protocol::wire_string("");
  } catch (...) {
    const protocol::ReplyError error = protocol::reply_error_from(std::current_exception());
    reply.status = error.status;
    reply.field = protocol::wire_string(error.field);
    reply.message = protocol::wire_string(error.message);
    const auto level = error.status == gearcoupling_STATUS_INTERNAL_ERROR ? spdlog::level::err
                                                                          : spdlog::level::warn;
    spdlog::log(level, "{} client={} seq={}: {} field=\"{}\": {}", protocol::to_string(kCalculation),
                protocol::hex_id(correlation.client_id), correlation.sequence_number,
                protocol::to_string(error.status), error.field, error.message);
  }

  write_reply<kCalculation>(correlation, std::shared_ptr<const void>(sample, &reply));
  const double service_time_s = std::chrono::duration<double>(Clock::now() - received).count();
  stats_.record(kCalculation, reply_outcome(reply.status), service_time_s);
  // Guarded: the arguments (hex_id formats a string) would otherwise be built for every reply,
  // on the round trip's own thread, with debug logging off.
  if (spdlog::should_log(spdlog::level::debug)) {
    spdlog::debug("{} client={} seq={} {} {:.1f} us", protocol::to_string(kCalculation),
                  protocol::hex_id(correlation.client_id), correlation.sequence_number,
                  protocol::to_string(reply.status), service_time_s * 1e6);
  }
}

// The request names a client_id whose reply readers belong to another participant than the
// request's writer: a forged client_id, which would send the reply to that other client. Dropped
// without a reply (docs/security.md): an error reply could only go to the client it names, who
// did not ask, and the forger's own partition is unknown.
void Service::refuse_forged(Calculation calculation, const gearcoupling_Correlation& correlation) {
  stats_.record_forged();
  spdlog::warn("{} client={} seq={}: refused, no reply: the request was not written by a "
               "participant that reads client {}'s replies (a forged client_id)",
               protocol::to_string(calculation), protocol::hex_id(correlation.client_id),
               correlation.sequence_number, protocol::hex_id(correlation.client_id));
}

void Service::admit(Calculation calculation, const gearcoupling_Correlation& correlation,
                    const std::optional<dds_guid_t>& requester, std::function<void()> job,
                    bool answer_here) {
  const Clock::time_point park_until = Clock::now() + seconds(config_.reply_match_timeout_s);
  const std::optional<ParticipantKey> from =
      requester ? std::optional<ParticipantKey>(participant_key_of(*requester)) : std::nullopt;
  switch (reply_writers_.admit(correlation.client_id, calculation, correlation.sequence_number,
                               from, job, park_until)) {
    case ReplyWriters::Admission::kRun:
      // Only while no request waits for a worker: otherwise the workers are the faster way.
      if (answer_here && pool_.queued() == 0) {
        stats_.record_answered_inline();
        job();
      } else {
        pool_.submit(std::move(job));
      }
      return;
    case ReplyWriters::Admission::kParked:
      return;
    case ReplyWriters::Admission::kForged:
      refuse_forged(calculation, correlation);
      return;
    case ReplyWriters::Admission::kDropped:
      // Debug only: a flood would otherwise flood the log; the counts are in the stats line.
      spdlog::debug("{} client={} seq={}: dropped unanswered: the client has departed or {} "
                    "requests already wait for their clients' reply readers",
                    protocol::to_string(calculation), protocol::hex_id(correlation.client_id),
                    correlation.sequence_number, kMaxParkedRequests);
      return;
  }
}

void Service::release_parked(bool final) {
  std::vector<UnmatchedRequest> expired;
  std::vector<ReplyWriters::Job> ready =
      reply_writers_.release(Clock::now(), config_.departed_hold_s, expired);
  for (ReplyWriters::Job& job : ready) pool_.submit(std::move(job));
  if (!expired.empty() && unlogged_unmatched_ == 0) first_unlogged_unmatched_ = expired.front();
  unlogged_unmatched_ += expired.size();
  // At most one line a second: a flood of made-up ids must not flood the log.
  const Clock::time_point now = Clock::now();
  if (unlogged_unmatched_ == 0 || (!final && now < next_unmatched_log_)) return;
  const UnmatchedRequest& e = first_unlogged_unmatched_;
  spdlog::warn("{} request(s) dropped unanswered: no reply reader of their client matched within "
               "{} s (--reply-match-timeout-s; a made-up client_id, or a client that did not wait "
               "for discovery), the first: {} client={} seq={}",
               unlogged_unmatched_, config_.reply_match_timeout_s,
               protocol::to_string(e.calculation), protocol::hex_id(e.client_id),
               e.sequence_number);
  unlogged_unmatched_ = 0;
  next_unmatched_log_ = now + std::chrono::seconds(1);
}

template <Calculation kCalculation>
void Service::write_reply(const gearcoupling_Correlation& correlation,
                          std::shared_ptr<const void> sample) {
  const dds_entity_t writer = reply_writers_.writer(correlation.client_id, kCalculation);
  // The writer never blocks (max blocking time 0): a full window is DDS_RETCODE_TIMEOUT.
  const dds_return_t rc = writer == 0 ? DDS_RETCODE_ALREADY_DELETED : dds_write(writer, sample.get());
  if (rc == DDS_RETCODE_OK) return;
  if (rc == DDS_RETCODE_TIMEOUT) {
    if (!reply_backlog_.hold({correlation.client_id, correlation.sequence_number, kCalculation,
                              writer, std::move(sample)})) {
      // Debug only: counted in the stats line, and a deaf client would flood the log.
      spdlog::debug("{} client={} seq={}: reply dropped: {} replies already wait for this "
                    "client, or {} for all clients that do not acknowledge",
                    protocol::to_string(kCalculation), protocol::hex_id(correlation.client_id),
                    correlation.sequence_number, kMaxBackloggedRepliesPerClient,
                    kMaxBackloggedReplies);
    }
  } else if (rc == DDS_RETCODE_BAD_PARAMETER || rc == DDS_RETCODE_ALREADY_DELETED) {
    spdlog::warn("{} client={} seq={}: reply not delivered: the client left while it was computed",
                 protocol::to_string(kCalculation), protocol::hex_id(correlation.client_id),
                 correlation.sequence_number);
  } else {
    spdlog::error("{} client={} seq={}: dds_write of the reply failed: {}",
                  protocol::to_string(kCalculation), protocol::hex_id(correlation.client_id),
                  correlation.sequence_number, dds_strretcode(rc));
  }
}

void Service::take_all_requests() {
  protocol::for_each_calculation(
      [&](auto calculation) { take_requests<decltype(calculation)::value>(); });
}

void Service::take_subscriptions() {
  for (;;) {
    protocol::LoanedSamples<dds_builtintopic_endpoint_t> samples(subscriptions_reader_.get());
    if (samples.size() == 0) return;
    for (std::size_t i = 0; i < samples.size(); ++i) {
      const dds_sample_info_t& info = samples.info(i);
      if (info.instance_state != DDS_IST_ALIVE) {
        const auto known = reply_readers_.find(info.instance_handle);
        if (known == reply_readers_.end()) continue;
        const ReplyReader& gone = known->second;
        reply_writers_.reader_gone(gone.client_id, gone.calculation, gone.participant);
        spdlog::debug("client={} left ({} reply reader gone)", protocol::hex_id(gone.client_id),
                      protocol::to_string(gone.calculation));
        reply_readers_.erase(known);
        continue;
      }
      if (!info.valid_data || reply_readers_.count(info.instance_handle) != 0) continue;
      const dds_builtintopic_endpoint_t& endpoint = samples[i];
      const auto calculation = protocol::calculation_of_reply_topic(endpoint.topic_name);
      if (!calculation || endpoint.qos == nullptr) continue;
      uint32_t count = 0;
      char** partitions = nullptr;
      if (!dds_qget_partition(endpoint.qos, &count, &partitions)) continue;
      for (uint32_t p = 0; p < count; ++p) {
        const auto client = protocol::client_id_of_reply_partition(partitions[p]);
        if (client && reply_readers_.count(info.instance_handle) == 0) {
          const ParticipantKey owner = participant_key_of(endpoint.participant_key);
          reply_writers_.reader_appeared(*client, *calculation, owner);
          reply_readers_.emplace(info.instance_handle, ReplyReader{*client, *calculation, owner});
          spdlog::debug("client={} {} reply reader discovered", protocol::hex_id(*client),
                        protocol::to_string(*calculation));
        }
        dds_free(partitions[p]);
      }
      dds_free(partitions);
    }
  }
}

void Service::log_stats() const {
  const auto snapshot = stats_.snapshot();
  std::string line;
  for (Calculation calculation : protocol::kAllCalculations) {
    const CalculationSnapshot& s = snapshot[protocol::index_of(calculation)];
    if (s.served + s.failed + s.refused == 0) continue;
    line += fmt::format(" {}: served={} refused={} failed={} p50={:.1f}us p99={:.1f}us;",
                        protocol::to_string(calculation), s.served, s.refused, s.failed,
                        s.p50_service_time_s * 1e6, s.p99_service_time_s * 1e6);
  }
  const AdmissionDrops drops = reply_writers_.drops();
  if (!line.empty()) line.pop_back();  // the last calculation's ';': the format adds one
  spdlog::info("stats: clients={} queued={} parked={} backlog={} answered_in_listener={}{}; "
               "dropped before work: "
               "unmatched={} parked_full={} departed={} forged={}; replies written late={} dropped={}",
               reply_writers_.clients(), pool_.queued(), reply_writers_.parked(),
               reply_backlog_.size(), stats_.answered_inline(), line.empty() ? " no requests yet" : line, drops.unmatched,
               drops.parked_full, drops.departed, stats_.forged(), reply_backlog_.written_late(),
               reply_backlog_.dropped());
}

void Service::publish_status() {
  std::lock_guard lock(status_mutex_);
  status_.publish(accepting_);
}

void Service::stop_accepting() {
  std::lock_guard lock(status_mutex_);
  accepting_ = false;
  status_.publish(false);
}

void Service::run() {
  spdlog::info("gearcoupling-service instance {} on domain {}: {} worker threads, catalogue [{}], "
               "requests in partition \"{}\"",
               protocol::hex_id(instance_id_), config_.domain, pool_.threads(), catalogue_.names(),
               protocol::request_partition(instance_id_));
  publish_status();
  // The status and the stats line on a clock, below the request path (periodic_work.h says why).
  PeriodicWork periodic({{seconds(config_.status_interval_s), [this] { publish_status(); }},
                         {seconds(config_.stats_log_interval_s), [this] { log_stats(); }}});
  std::optional<Clock::time_point> stop_at;
  bool moving_writers = false;  // reply writers are moving to a new reply domain: poll
  for (;;) {
    Clock::time_point now = Clock::now();
    if (stop_requested_ && !stop_at) {
      if (reload_requested_) {
        // No grace: the clients resend what this instance leaves unanswered to the next one.
        stop_at = now;
        spdlog::info("reloading: answering the requests taken, then a new participant");
      } else {
        stop_at = now + seconds(config_.shutdown_grace_s);
        stop_accepting();
        spdlog::info("shutting down: answering requests in flight for {} s",
                     config_.shutdown_grace_s);
      }
    }
    if (stop_at && now >= *stop_at) break;
    // At least once a status interval, as when the status was written here: a writer whose
    // move to a new reply domain waits (ReplyWriters::move_writers) is looked at again.
    Clock::time_point wake = now + seconds(config_.status_interval_s);
    if (stop_at) wake = std::min(wake, *stop_at);
    if (reply_writers_.parked() > 0 || moving_writers) wake = std::min(wake, now + kParkedPoll);
    const auto timeout = std::chrono::duration_cast<std::chrono::nanoseconds>(wake - now).count();
    dds_waitset_wait(waitset_.get(), nullptr, 0, std::max<int64_t>(timeout, 0));
    bool triggered = false;
    dds_take_guardcondition(guard_.get(), &triggered);
    take_subscriptions();
    take_all_requests();
    release_parked(false);
    moving_writers = reply_writers_.move_writers(Clock::now());
  }
  periodic.stop();
  for (const Entity& reader : request_readers_) dds_set_listener(reader.get(), nullptr);
  take_all_requests();
  release_parked(true);
  if (const std::size_t parked = reply_writers_.parked(); parked > 0) {
    spdlog::warn("shutting down: {} request(s) dropped unanswered: their client's reply reader "
                 "had not matched yet (a made-up client_id, or a client that did not wait for "
                 "discovery)",
                 parked);
  }
  pool_.drain_and_stop();
  reply_backlog_.stop();
  log_stats();
  status_.dispose();
  spdlog::info("instance {} stopped", protocol::hex_id(instance_id_));
}

}  // namespace gc::service
