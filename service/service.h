// One gearcoupling-service instance: readers for the five request topics in this instance's own
// request partition, a pool of workers computing with the core, reply writers per client, the
// status topic. run() serves until request_stop(), then answers what has arrived and returns.
#pragma once

#include <array>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <exception>
#include <map>
#include <mutex>
#include <optional>

#include "protocol/calculation.h"
#include "protocol/calculation_traits.h"
#include "protocol/dds_entity.h"
#include "protocol/requests.h"
#include "service/catalogue.h"
#include "service/reply_backlog.h"
#include "service/reply_writers.h"
#include "service/requesters.h"
#include "service/service_config.h"
#include "service/service_stats.h"
#include "service/status_publisher.h"
#include "service/worker_pool.h"

namespace gc::service {

class Service {
 public:
  /// Joins DDS domain config.domain with the Cyclone configuration `dds` (protocol/dds_config.h:
  /// CYCLONEDDS_URI, else the installed one) and creates every entity. Throws protocol::DdsError
  /// when DDS cannot start.
  Service(const ServiceConfig& config, Catalogue catalogue, const protocol::DdsConfig& dds);
  ~Service();
  Service(const Service&) = delete;
  Service& operator=(const Service&) = delete;

  /// Serves requests until request_stop(); then keeps answering for config.shutdown_grace_s
  /// (status says accepting = false), answers everything received, disposes its status.
  void run();
  /// Safe from any thread (not from a signal handler: use a signal-waiting thread).
  void request_stop();
  /// As request_stop(), without the grace period: run() answers what has arrived and returns at
  /// once, so that the caller can make a new Service (a new participant: Cyclone reads the
  /// identity, the CRL and the permissions again; docs/security.md, "Revoking an identity").
  void request_reload();

  std::uint64_t instance_id() const { return instance_id_; }

 private:
  template <protocol::Calculation kCalculation>
  void take_requests();
  template <protocol::Calculation kCalculation>
  void answer(const gearcoupling_Correlation& correlation,
              const std::optional<dds_guid_t>& requester,
              const std::optional<typename protocol::CalculationTraits<kCalculation>::Request>& request,
              std::exception_ptr malformed, std::chrono::steady_clock::time_point received);
  void refuse_forged(protocol::Calculation calculation,
                     const gearcoupling_Correlation& correlation);
  /// Runs `job` (a request of `client_id`) if its reply writer is matched: here when
  /// `answer_here` and no job waits for a worker, else on a worker. Otherwise parks it
  /// (ReplyWriters::admit) or drops it: no thread waits for a client's reader.
  void admit(protocol::Calculation calculation, const gearcoupling_Correlation& correlation,
             const std::optional<dds_guid_t>& requester, std::function<void()> job,
             bool answer_here);
  /// Parked requests whose reader matched go to the workers; the expired are logged, at most
  /// once a second unless `final`.
  void release_parked(bool final);
  template <protocol::Calculation kCalculation>
  void write_reply(const gearcoupling_Correlation& correlation,
                   std::shared_ptr<const void> sample);
  void take_all_requests();
  void take_subscriptions();
  void log_stats() const;
  /// Writes the status, accepting while accepting_ (PeriodicWork's thread and run()).
  void publish_status();
  /// From now on the status says accepting = false (written at once).
  void stop_accepting();

  ServiceConfig config_;
  Catalogue catalogue_;
  std::uint64_t instance_id_;
  /// The domain this Service made for the installed configuration (protocol::create_participant
  /// makes it explicitly, and Cyclone keeps an explicit domain after its last participant):
  /// deleted after the participant, so that the next Service (a reload) reads the configuration
  /// again. Empty when Cyclone made the domain itself (CYCLONEDDS_URI, or its default).
  protocol::Entity domain_;
  protocol::Entity participant_;
  std::array<protocol::Entity, gc::protocol::kCalculationCount> request_topics_;
  protocol::Entity request_subscriber_;
  std::array<protocol::Entity, gc::protocol::kCalculationCount> request_readers_;
  protocol::Entity subscriptions_reader_;  ///< DCPSSubscription: clients' reply readers
  protocol::Entity guard_;
  protocol::Entity waitset_;
  /// Clients' reply readers discovered: their client, calculation and participant.
  struct ReplyReader {
    std::uint64_t client_id;
    protocol::Calculation calculation;
    ParticipantKey participant;
  };
  std::map<dds_instance_handle_t, ReplyReader> reply_readers_;
  ServiceStats stats_;
  Requesters requesters_;  ///< who wrote each request; whether a reply writer reaches them
  ReplyWriters reply_writers_;
  ReplyBacklog reply_backlog_;
  StatusPublisher status_;
  std::mutex status_mutex_;  ///< one status write at a time, with accepting_ as it is then
  bool accepting_ = true;
  std::atomic<bool> stop_requested_{false};
  std::atomic<bool> reload_requested_{false};
  // Parked requests dropped and not yet logged (dispatch loop only).
  std::uint64_t unlogged_unmatched_ = 0;
  UnmatchedRequest first_unlogged_unmatched_;
  std::chrono::steady_clock::time_point next_unmatched_log_{};
  WorkerPool pool_;  ///< last: destroyed (drained) first
};

}  // namespace gc::service
