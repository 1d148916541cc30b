// One reply writer per (client, calculation), each in that client's own reply partition
// ("gearcoupling.reply.<client id>"), so a reply travels only to the client that asked, on the
// wire. Writers are created only when discovery reports a client's reply reader (before the
// client may send, see docs/protocol.md) and deleted when the reader goes: a request carrying an
// id no reader has (made up, 0, or a client that did not wait for discovery) creates nothing.
// Every writer carries this instance's id as USER_DATA, by which a client knows this instance's
// writer has matched its reader. Writers are KEEP_LAST (protocol::tagged_reply_writer_qos): any
// participant may put a reader in a client's partition, and one that never acknowledges must
// not hold the writer; a KEEP_LAST writer never waits for a reader (issue 38).
//
// The writers live in a ReplyDomain, not on the service's participant: Cyclone 0.10.2 keeps
// memory for every writer deleted until its domain goes (service/reply_domain.h). After
// `writers_per_domain` writers a new domain takes the new writers; the writers of clients still
// there move to it (a successor writer in the new domain takes over once it has matched the
// client's readers), and the old domain is deleted with its last writer. So clients coming and
// going cost a bounded amount, whatever how many came.
//
// Match before compute: admit() lets a request reach the workers only once its reply writer is
// matched. Until then the request is parked here, outside the workers, for a bounded time and in
// a bounded number; release() hands over those whose reader appeared and drops the expired.
// Nothing here blocks.
//
// A client_id is not a capability (issue 23): what a request can do to a client (park, put it on
// hold) is bound to the participant that wrote the request. A client's reply readers name their
// participants (discovery); a request from another participant for a client that has readers is
// refused at once as forged. Another participant is one with no reader among the client's reply
// readers: neither reported by the built-in topics nor, before its report, matched with the
// client's writer (an eavesdropper's reader reported first made the client itself a forger). The hold after an unmatched request expires covers only
// (client_id, the requesting participant). So a request carrying someone else's id costs that
// client nothing. Under DDS Security the participant is authenticated (docs/security.md).
#pragma once

#include <array>
#include <chrono>
#include <cstdint>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <dds/dds.h>

#include "protocol/calculation.h"
#include "protocol/dds_entity.h"
#include "service/reply_domain.h"

namespace gc::service {

/// Requests dropped before any work was spent on them, since the start.
struct AdmissionDrops {
  std::uint64_t unmatched = 0;    ///< parked until their deadline, no reply reader appeared
  std::uint64_t parked_full = 0;  ///< arrived while the parked requests were at their limit
  std::uint64_t departed = 0;     ///< from a client whose readers went or stopped acknowledging
                                  ///< (or from a participant held for that client's id)
};

/// A participant's GUID (dds_builtintopic_endpoint_t::participant_key), comparable.
using ParticipantKey = std::array<unsigned char, 16>;
ParticipantKey participant_key_of(const dds_guid_t& guid);

/// A parked request given up on, for the log.
struct UnmatchedRequest {
  std::uint64_t client_id = 0;
  std::uint64_t sequence_number = 0;
  protocol::Calculation calculation{};
};

class ReplyWriters {
 public:
  using Clock = std::chrono::steady_clock;
  using Job = std::function<void()>;
  using MakeDomain = std::function<std::unique_ptr<ReplyDomain>()>;
  enum class Admission { kRun, kParked, kDropped, kForged };

  /// Writers made in one reply domain before the next takes over. A domain's heap grows by 1-2
  /// kB for each client that came and went (what Cyclone keeps of the writers deleted and of
  /// the clients gone, measured ten clients a second), all freed when it is deleted: 256
  /// clients bound that to well under 1 MiB. A new domain costs a
  /// participant that every client discovers, a few threads and sockets for the moment two
  /// domains overlap, and the move of every connected client's writers: at one client a second,
  /// once every 4 minutes.
  static constexpr std::size_t kWritersPerDomain = 256;
  /// Writers moved (successors made) per move_writers() call: a domain's turn never stalls the
  /// dispatch loop for long, however many clients are connected.
  static constexpr std::size_t kMovesPerCall = 16;

  /// `make_domain()` makes the domain the writers are made in (ReplyDomain), at the start and
  /// after every `writers_per_domain` writers. A moved client's old writer is deleted
  /// `moved_writer_linger_s` after its successor took over: a worker, or the ReplyBacklog for up
  /// to its hold time, may still be writing a reply with it. At most
  /// `max_parked` requests wait for their client's reader at once. `on_first_parked` is called
  /// (under no lock of this class) when a request is parked while none was: the dispatch loop
  /// then polls release() until none is left.
  /// A client whose readers all went is remembered (its late requests dropped at once) for
  /// `departed_memory_s`, then forgotten: clients that come and go (every CLI call is one) must
  /// not grow the service without bound.
  /// A successor that has not matched as many readers as the writer it replaces within
  /// `move_give_up_s` is deleted and the client stays in its domain (a client that never
  /// discovers the new domain's participant, e.g. one whose peer list is full, is still served,
  /// and the dispatch loop does not poll for it); the move is tried again 10 times as late.
  ReplyWriters(MakeDomain make_domain, std::string instance_tag, std::size_t max_parked,
               std::function<void()> on_first_parked, double departed_memory_s = 60.0,
               std::size_t writers_per_domain = kWritersPerDomain,
               double moved_writer_linger_s = 2.0, double move_give_up_s = 30.0);

  /// A reader of `calculation`'s replies, of participant `owner`, appeared in `client_id`'s
  /// partition: make its writer.
  void reader_appeared(std::uint64_t client_id, protocol::Calculation calculation,
                       const ParticipantKey& owner);
  /// That reader went (the client left): delete the writer once no reader of it remains.
  void reader_gone(std::uint64_t client_id, protocol::Calculation calculation,
                   const ParticipantKey& owner);

  /// Without blocking, for a request of `client_id` written by participant `requester` (nullopt
  /// when its writer is no longer known): kForged when `client_id` has reply readers and none is
  /// `requester`'s, by discovery's reports or the writer's matches (the request names someone
  /// else's id; nothing is kept); kRun when (client,
  /// calculation)'s writer is matched (the caller runs `job`); kParked when it is not (yet):
  /// `job` is kept until `park_until`; kDropped when the client has departed, `requester` is
  /// held for this id, or the parked requests are at their limit (`job` is left as it was).
  Admission admit(std::uint64_t client_id, protocol::Calculation calculation,
                  std::uint64_t sequence_number, const std::optional<ParticipantKey>& requester,
                  Job& job, Clock::time_point park_until);

  /// Parked jobs whose writer has matched since (for the workers); drops the parked requests
  /// past their time into `expired`, and holds (their client, their requesting participant) for
  /// `hold_s`: that participant's further requests for that id are dropped at once, nobody
  /// else's.
  std::vector<Job> release(Clock::time_point now, double hold_s,
                           std::vector<UnmatchedRequest>& expired);
  /// Requests parked now.
  std::size_t parked() const;
  AdmissionDrops drops() const;

  /// The writer for (client, calculation), or 0 when it is gone (the client left).
  dds_entity_t writer(std::uint64_t client_id, protocol::Calculation calculation) const;

  /// A reply to `client_id` could not be delivered in time (a killed client whose reader has not
  /// yet expired): drop its further requests at once, for `hold_s` or until one of its readers
  /// appears again, instead of spending work on them.
  void mark_departed(std::uint64_t client_id, double hold_s);

  /// Moves up to kMovesPerCall writers of replaced domains to the current one (makes their
  /// successors), hands over to the successors that have matched as many readers, gives up on
  /// those that did not in time, and deletes the old writers whose linger is over (a domain goes
  /// with its last writer). True while a move is under way: call again soon (a move given up on
  /// is not: it is tried again at a later call). Dispatch loop only, as reader_appeared().
  bool move_writers(Clock::time_point now);
  /// Reply domains alive (the current one and the replaced ones some writer is still in).
  std::size_t domains() const;

  /// Clients with at least one writer.
  std::size_t clients() const;
  /// Client ids remembered as departed or held (bounded: forgotten when their time is up).
  std::size_t remembered_departures() const;

 private:
  /// A reply domain and how many writers were made in it.
  struct Generation {
    std::unique_ptr<ReplyDomain> domain;
    std::size_t writers_made = 0;
  };
  /// A writer in its own publisher (the client's partition), in a generation's domain.
  struct Endpoint {
    std::shared_ptr<Generation> generation;  ///< first: the domain outlives the entities in it
    protocol::Entity publisher;
    protocol::Entity writer;
  };
  struct Writer {
    Endpoint endpoint;
    Endpoint successor;    ///< in the current domain, while `endpoint` is in a replaced one
    Clock::time_point successor_made;   ///< when `successor` was made
    Clock::time_point move_again;       ///< a move given up on is not tried before this
    int readers = 0;       ///< discovered readers of this (client, calculation)
    bool matched = false;  ///< a reader has matched it (sticky: it goes only with the reader)
  };
  /// A moved client's old writer, kept until `until` for the handles still in use.
  struct Lingering {
    Endpoint endpoint;
    Clock::time_point until;
  };
  struct Parked {
    std::uint64_t sequence_number;
    ParticipantKey requester;  ///< all zero when unknown
    Clock::time_point until;
    Job job;
  };
  using Key = std::pair<std::uint64_t, int>;

  /// The generation a new writer goes in: a new one once the current one has had its share
  /// (its domain made without mutex_). Dispatch loop only.
  std::shared_ptr<Generation> generation_for_new_writer();
  Endpoint make_endpoint(std::shared_ptr<Generation> generation, const Key& key) const;
  bool matched_locked(const Key& key);
  /// True when (client, calculation)'s writer is matched with a reader of `requester`: the
  /// client's own reader, which Cyclone matched before the dispatch loop took its discovery report
  /// (then an eavesdropper's reader, reported first, made the client look like a forger).
  bool reads_own_replies_locked(const Key& key, const ParticipantKey& requester);
  bool departed_locked(std::uint64_t client_id, Clock::time_point now);
  bool held_locked(std::uint64_t client_id, const ParticipantKey& requester, Clock::time_point now);
  void mark_departed_locked(std::uint64_t client_id, Clock::time_point until);
  /// Forgets the departed and held entries whose time is up, once they are many (amortised:
  /// the next sweep waits until their number has doubled).
  void prune_locked(Clock::time_point now);

  MakeDomain make_domain_;
  std::string instance_tag_;
  std::size_t writers_per_domain_;
  Clock::duration moved_writer_linger_;
  Clock::duration move_give_up_;
  std::size_t max_parked_;
  std::function<void()> on_first_parked_;
  Clock::duration departed_memory_;
  std::size_t prune_at_;  ///< departed_ or held_ entries at which prune_locked() sweeps
  mutable std::mutex mutex_;
  std::shared_ptr<Generation> current_;
  bool replaced_domains_ = false;  ///< some writer may be in a replaced domain
  std::vector<Lingering> lingering_;
  std::map<Key, Writer> writers_;
  std::map<Key, std::deque<Parked>> parked_;
  std::size_t parked_count_ = 0;
  AdmissionDrops drops_;
  /// Clients whose readers all went or who stopped acknowledging, until when: only the client's
  /// own readers can cause either.
  std::map<std::uint64_t, Clock::time_point> departed_;
  /// (client, requesting participant) whose parked request expired unmatched (until then).
  std::map<std::pair<std::uint64_t, ParticipantKey>, Clock::time_point> held_;
  /// The participants owning each client's discovered reply readers (how many readers each).
  std::map<std::uint64_t, std::map<ParticipantKey, int>> owners_;
};

}  // namespace gc::service
