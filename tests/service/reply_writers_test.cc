// Clients that come and go cost ReplyWriters a bounded amount, whatever how many came: the
// soak's reconnecting client (bench/soak.sh) and every CLI call are such clients, and a service
// that grew with each would grow for as long as it runs. It remembers a client whose reply
// readers all went for a bounded time only, and its writers live in reply domains that it
// replaces and deletes (with what Cyclone 0.10.2 keeps of every writer deleted in them,
// service/reply_domain.h), moving the writers of the clients still there.
#include "service/reply_writers.h"

#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <thread>

#include <dds/dds.h>

#include "protocol/dds_config.h"
#include "protocol/dds_entity.h"
#include "protocol/matching.h"
#include "protocol/names.h"
#include "protocol/qos.h"
#include "protocol/topics.h"
#include "tests/service/service_process.h"

namespace gc::service {
namespace {

using protocol::Calculation;

/// A client (reply reader of jam angles, on participant `owner`) appears and goes again.
void come_and_go(ReplyWriters& writers, std::uint64_t client_id, const ParticipantKey& owner) {
  writers.reader_appeared(client_id, Calculation::kJamAngle, owner);
  writers.reader_gone(client_id, Calculation::kJamAngle, owner);
}

class ReplyWritersTest : public testing::Test {
 protected:
  protocol::Entity participant_{protocol::create_participant(test::test_domain(), protocol::dds_config())};
  std::array<protocol::Entity, gc::protocol::kCalculationCount> topics_ = protocol::make_reply_topics(participant_.get());
  const ParticipantKey owner_{1};
  ReplyWriters::MakeDomain make_domain_ = [] {
    return std::make_unique<ReplyDomain>(test::test_domain(), protocol::dds_config());
  };

  /// A client's jam-angle reply reader, in its partition on this process's other participant.
  struct ClientReader {
    protocol::Entity subscriber, reader;
  };
  ClientReader jam_angle_reader(std::uint64_t client_id) const {
    const protocol::Qos partition = protocol::partition_qos(protocol::reply_partition(client_id));
    ClientReader r;
    r.subscriber = protocol::Entity(protocol::check_dds(
        dds_create_subscriber(participant_.get(), partition.get(), nullptr), "dds_create_subscriber"));
    const protocol::Qos qos = protocol::request_reply_qos();
    const std::size_t jam = protocol::index_of(Calculation::kJamAngle);
    r.reader = protocol::Entity(protocol::check_dds(
        dds_create_reader(r.subscriber.get(), topics_[jam].get(), qos.get(), nullptr), "dds_create_reader"));
    return r;
  }
};

/// Calls move_writers() until it says no move is under way; false if that took over `limit`.
bool move_until_done(ReplyWriters& writers, std::chrono::seconds limit) {
  const auto until = ReplyWriters::Clock::now() + limit;
  while (writers.move_writers(ReplyWriters::Clock::now())) {
    if (ReplyWriters::Clock::now() > until) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return true;
}

TEST_F(ReplyWritersTest, ClientsThatCameAndWentAreForgottenOnceTheirTimeIsUp) {
  ReplyWriters writers(make_domain_, "0123456789abcdef", 16, [] {}, 0.001);
  constexpr std::uint64_t kClients = 4096 + 100;  // past the sweep's threshold
  for (std::uint64_t id = 1; id <= kClients; ++id) come_and_go(writers, id, owner_);
  EXPECT_LT(writers.remembered_departures(), 4096u) << "remembered forever, they grow with every client that left";
}

TEST_F(ReplyWritersTest, AClientJustGoneIsStillRememberedAndItsLateRequestsDropped) {
  ReplyWriters writers(make_domain_, "0123456789abcdef", 16, [] {}, 60.0);
  come_and_go(writers, 7, owner_);
  EXPECT_EQ(writers.remembered_departures(), 1u);
  ReplyWriters::Job job = [] {};
  EXPECT_EQ(writers.admit(7, Calculation::kJamAngle, 1, owner_, job, ReplyWriters::Clock::now() + std::chrono::seconds(1)),
            ReplyWriters::Admission::kDropped);
}

TEST_F(ReplyWritersTest, ClientsThatComeAndGoLeaveAtMostTwoReplyDomainsAndAStayingClientIsStillServed) {
  constexpr std::size_t kWritersPerDomain = 8;
  ReplyWriters writers(make_domain_, "0123456789abcdef", 16, [] {}, 60.0, kWritersPerDomain, 0.0);
  // A client that stays.
  constexpr std::uint64_t kStaying = 0x5747;
  const ClientReader reader = jam_angle_reader(kStaying);
  writers.reader_appeared(kStaying, Calculation::kJamAngle, owner_);
  // Then 100 clients come and go: 12 domains' worth of writers.
  for (std::uint64_t id = 1; id <= 100; ++id) {
    come_and_go(writers, id, owner_);
    ASSERT_TRUE(move_until_done(writers, std::chrono::seconds(30))) << "client " << id;
  }
  // The staying client's writer moved with every new domain, and nothing else was kept: the
  // current domain, and at most the one it is leaving (here none, after the last move).
  EXPECT_LE(writers.domains(), 2u) << "the replaced domains (and what Cyclone keeps in them) grow with every client";
  EXPECT_EQ(writers.clients(), 1u);
  const dds_entity_t writer = writers.writer(kStaying, Calculation::kJamAngle);
  ASSERT_NE(writer, 0);
  // Matching is asynchronous: allow it 10 s, far more than loopback discovery takes.
  for (int i = 0; i < 1000 && protocol::matched_reader_count(writer) == 0; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  EXPECT_GE(protocol::matched_reader_count(writer), 1u) << "the moved writer reaches the staying client";
}

// A client whose readers never match the new reply domain's writer (here: the new domains are
// seen on another DDS domain; in the field, a client whose peer list cannot take one more
// participant): the move is given up on after move_give_up_s, the dispatch loop is not kept
// polling, and the client is still served by its writer in the old domain.
TEST_F(ReplyWritersTest, AMoveWhoseSuccessorNeverMatchesIsGivenUpAndTheClientStillServed) {
  int made = 0;
  const int elsewhere = (test::test_domain() + 1) % 230;
  ReplyWriters::MakeDomain make_domain = [&] {
    return std::make_unique<ReplyDomain>(made++ == 0 ? test::test_domain() : elsewhere, protocol::dds_config());
  };
  ReplyWriters writers(make_domain, "0123456789abcdef", 16, [] {}, 60.0, 1, 0.0, 1.0);
  constexpr std::uint64_t kStaying = 0x5748;
  const ClientReader reader = jam_angle_reader(kStaying);
  writers.reader_appeared(kStaying, Calculation::kJamAngle, owner_);
  const dds_entity_t first = writers.writer(kStaying, Calculation::kJamAngle);
  ASSERT_NE(first, 0);
  for (int i = 0; i < 1000 && protocol::matched_reader_count(first) == 0; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ASSERT_GE(protocol::matched_reader_count(first), 1u);
  come_and_go(writers, 1, owner_);   // the first domain has had its one writer: a new one is made
  ASSERT_EQ(made, 2);
  const auto started = ReplyWriters::Clock::now();
  ASSERT_TRUE(move_until_done(writers, std::chrono::seconds(20))) << "the move was never given up";
  const double took_s = std::chrono::duration<double>(ReplyWriters::Clock::now() - started).count();
  EXPECT_GE(took_s, 0.9) << "given up before its time";
  EXPECT_LT(took_s, 10.0);
  EXPECT_FALSE(writers.move_writers(ReplyWriters::Clock::now())) << "a move given up on keeps the loop polling";
  EXPECT_EQ(writers.writer(kStaying, Calculation::kJamAngle), first) << "the client lost its writer";
  EXPECT_GE(protocol::matched_reader_count(first), 1u);
  EXPECT_EQ(writers.domains(), 2u);   // the old domain stays while the client is in it
}

// The discovery race behind a flaky Service.RepliesOnlyToTheRequestingClient: a participant that
// reads a client's partition (an eavesdropper) is reported by the built-in topics before the
// client's own reply reader. The client, which waited for the writer to match it as the protocol
// asks, had its first request refused as forged and waited out its call. Cyclone's writer already
// matched the client's reader: that makes the client an owner. A participant with no reader there
// is still refused.
TEST_F(ReplyWritersTest, AClientWhoseReaderIsMatchedButNotYetReportedIsNotTakenForAForger) {
  ReplyWriters writers(make_domain_, "0123456789abcdef", 16, [] {});
  constexpr std::uint64_t kClient = 0x5749;
  const ClientReader reader = jam_angle_reader(kClient);  // the client's own, on participant_
  dds_guid_t guid{};
  ASSERT_EQ(dds_get_guid(participant_.get(), &guid), DDS_RETCODE_OK);
  const ParticipantKey client = participant_key_of(guid);
  const ParticipantKey eavesdropper{7}, forger{9};
  writers.reader_appeared(kClient, Calculation::kJamAngle, eavesdropper);  // reported first
  const dds_entity_t writer = writers.writer(kClient, Calculation::kJamAngle);
  ASSERT_NE(writer, 0);
  ASSERT_TRUE(protocol::wait_until([&] { return protocol::matched_reader_count(writer) >= 1; },
                                   std::chrono::steady_clock::now() + std::chrono::seconds(10)));
  int ran = 0;
  const auto admit = [&](const ParticipantKey& from) {
    ReplyWriters::Job job = [&ran] { ran += 1; };
    return writers.admit(kClient, Calculation::kJamAngle, 1, from, job,
                         ReplyWriters::Clock::now() + std::chrono::seconds(1));
  };
  EXPECT_EQ(admit(forger), ReplyWriters::Admission::kForged);
  EXPECT_EQ(admit(client), ReplyWriters::Admission::kRun) << "the client's own reader is matched: no forger";
  // Once its report comes, it is an owner as before.
  writers.reader_appeared(kClient, Calculation::kJamAngle, client);
  EXPECT_EQ(admit(client), ReplyWriters::Admission::kRun);
  EXPECT_EQ(admit(forger), ReplyWriters::Admission::kForged);
}

}  // namespace
}  // namespace gc::service
