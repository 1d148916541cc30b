// ReplyWriters remembers a client whose reply readers all went for a bounded time only: the
// soak's reconnecting client (bench/soak.sh) and every CLI call are such clients, and a
// service that remembered each forever would grow for as long as it runs.
#include "service/reply_writers.h"

#include <gtest/gtest.h>

#include <array>
#include <chrono>

#include "protocol/dds_config.h"
#include "protocol/dds_entity.h"
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
  std::array<protocol::Entity, 5> topics_ = protocol::make_reply_topics(participant_.get());
  const ParticipantKey owner_{1};
};

TEST_F(ReplyWritersTest, ClientsThatCameAndWentAreForgottenOnceTheirTimeIsUp) {
  ReplyWriters writers(participant_.get(), protocol::handles(topics_), "0123456789abcdef", 16, [] {}, 0.001);
  constexpr std::uint64_t kClients = 4096 + 100;  // past the sweep's threshold
  for (std::uint64_t id = 1; id <= kClients; ++id) come_and_go(writers, id, owner_);
  EXPECT_LT(writers.remembered_departures(), 4096u) << "remembered forever, they grow with every client that left";
}

TEST_F(ReplyWritersTest, AClientJustGoneIsStillRememberedAndItsLateRequestsDropped) {
  ReplyWriters writers(participant_.get(), protocol::handles(topics_), "0123456789abcdef", 16, [] {}, 60.0);
  come_and_go(writers, 7, owner_);
  EXPECT_EQ(writers.remembered_departures(), 1u);
  ReplyWriters::Job job = [] {};
  EXPECT_EQ(writers.admit(7, Calculation::kJamAngle, 1, owner_, job, ReplyWriters::Clock::now() + std::chrono::seconds(1)),
            ReplyWriters::Admission::kDropped);
}

}  // namespace
}  // namespace gc::service
