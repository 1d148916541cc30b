// Only the requesting client receives its reply, on the wire: replies are written in the
// requesting client's own partition, so DDS never matches them with another client's reader
// and never sends them to it (docs/protocol.md).
#include <gtest/gtest.h>

#include "client/client.h"
#include "protocol/calculation_traits.h"
#include "protocol/matching.h"
#include "protocol/names.h"
#include "protocol/qos.h"
#include "protocol/samples.h"
#include "protocol/topics.h"
#include "tests/service/service_process.h"

namespace gc {
namespace {

using protocol::Calculation;
using protocol::CatalogueName;
using protocol::check_dds;
using protocol::Entity;

/// A raw DDS reader of jam-angle replies in one partition, on its own participant.
class ReplyEavesdropper {
 public:
  explicit ReplyEavesdropper(const std::string& partition)
      : participant_(check_dds(dds_create_participant(test::test_domain(), nullptr, nullptr),
                               "dds_create_participant")),
        topics_(protocol::make_reply_topics(participant_.get())) {
    const protocol::Qos partition_qos = protocol::partition_qos(partition);
    subscriber_ = Entity(check_dds(
        dds_create_subscriber(participant_.get(), partition_qos.get(), nullptr), "subscriber"));
    const protocol::Qos qos = protocol::request_reply_qos();
    reader_ = Entity(check_dds(
        dds_create_reader(subscriber_.get(),
                          topics_[protocol::index_of(Calculation::kJamAngle)].get(), qos.get(),
                          nullptr),
        "reader"));
  }

  /// Samples received so far (taken).
  int take_count() {
    for (;;) {
      protocol::LoanedSamples<gearcoupling_JamAngleReply> samples(reader_.get());
      if (samples.size() == 0) return count_;
      for (std::size_t i = 0; i < samples.size(); ++i) count_ += samples.info(i).valid_data;
    }
  }
  dds_entity_t reader() const { return reader_.get(); }

 private:
  Entity participant_;
  std::array<Entity, gc::protocol::kCalculationCount> topics_;
  Entity subscriber_;
  Entity reader_;
  int count_ = 0;
};

/// Partitions of every writer matched with `reader`.
std::vector<std::string> matched_writer_partitions(dds_entity_t reader) {
  std::vector<dds_instance_handle_t> handles(64);
  const dds_return_t n = dds_get_matched_publications(reader, handles.data(), handles.size());
  std::vector<std::string> out;
  for (dds_return_t i = 0; i < n; ++i) {
    dds_builtintopic_endpoint_t* endpoint = dds_get_matched_publication_data(reader, handles[i]);
    uint32_t count = 0;
    char** partitions = nullptr;
    if (endpoint != nullptr && dds_qget_partition(endpoint->qos, &count, &partitions)) {
      for (uint32_t p = 0; p < count; ++p) {
        out.emplace_back(partitions[p]);
        dds_free(partitions[p]);
      }
      dds_free(partitions);
    }
    dds_builtintopic_free_endpoint(endpoint);
  }
  return out;
}

TEST(Service, RepliesOnlyToTheRequestingClient) {
  constexpr int kRequests = 300;
  test::ServiceProcess service;
  client::Client asking({test::test_domain(), std::chrono::seconds(20)});
  client::Client idle({test::test_domain(), std::chrono::seconds(20)});
  ASSERT_TRUE(idle.wait_for_service(Calculation::kJamAngle, std::chrono::seconds(10)));
  ASSERT_TRUE(asking.wait_for_service(Calculation::kJamAngle, std::chrono::seconds(10)));
  // One answered call first: the service then knows the asking client's own reply reader. Had it
  // discovered the eavesdropper below first (another participant reading that client's replies),
  // the client's request would be refused as a forged client_id (docs/security.md): under CI's
  // load it was, and the call waited out its 20 s.
  asking.call<Calculation::kJamAngle>({CatalogueName{"nrel_upwind"}});
  // A reader in the idle client's partition (as that client) and one in the asking client's
  // partition (the positive control: the same reader does receive what is sent there).
  ReplyEavesdropper as_idle(protocol::reply_partition(idle.client_id()));
  ReplyEavesdropper as_asking(protocol::reply_partition(asking.client_id()));
  // The eavesdroppers are discovered by the service like any reply reader; wait for theirs.
  ASSERT_TRUE(protocol::wait_until(
      [&] { return !matched_writer_partitions(as_asking.reader()).empty(); },
      std::chrono::steady_clock::now() + std::chrono::seconds(10)));

  for (int r = 0; r < kRequests; ++r) {
    asking.call<Calculation::kJamAngle>({CatalogueName{"nrel_upwind"}});
  }
  // Reliable delivery to the control reader completes within moments of the last reply.
  protocol::wait_until([&] { return as_asking.take_count() >= kRequests; },
                       std::chrono::steady_clock::now() + std::chrono::seconds(5));

  EXPECT_EQ(as_asking.take_count(), kRequests);
  EXPECT_EQ(as_idle.take_count(), 0);
  EXPECT_EQ(idle.counters().foreign, 0u);
  EXPECT_EQ(idle.counters().replies, 0u);
  EXPECT_EQ(asking.counters().replies, static_cast<std::uint64_t>(kRequests) + 1);
  // On the wire: no writer of the asking client's replies is even matched with the idle
  // client's reader, so DDS sends it nothing.
  const std::vector<std::string> idle_partitions = matched_writer_partitions(as_idle.reader());
  EXPECT_FALSE(idle_partitions.empty());  // the service's writer for the idle client itself
  for (const std::string& partition : idle_partitions) {
    EXPECT_EQ(partition, protocol::reply_partition(idle.client_id()));
  }
}

}  // namespace
}  // namespace gc
