// A careless or hostile client, in a process of its own (a reader whose history is full blocks
// its whole process's DDS delivery in Cyclone 0.10, so it cannot share one with the clients it
// is measured against). Used by misbehaving_clients_test.cc and
// bench/misbehaving_clients_bench.sh.
//
//   misbehaving_client DOMAIN fake-ids SECONDS   one jam-angle request per 10 ms for SECONDS,
//                                                each from a made-up client id (the first 0),
//                                                then 1100 more at once
//   misbehaving_client DOMAIN deaf SECONDS       10 tooth-contact requests (replies of about
//                                                2 kB) per 10 ms for SECONDS from a client whose
//                                                reply reader holds at most 100 replies and is
//                                                never read; then it stays, still not reading,
//                                                for 8 s more. Its own delivery (and so the
//                                                acknowledgements of its requests) stalls once
//                                                the reader is full: its writes then time out,
//                                                which it ignores.
//
// Exit status: 0 done, 2 usage, 3 no service found.
#include <unistd.h>

#include <cstdlib>
#include <string>
#include <thread>

#include "client/client.h"
#include "protocol/matching.h"
#include "protocol/names.h"
#include "protocol/qos.h"
#include "protocol/random_id.h"
#include "protocol/samples.h"
#include "protocol/topics.h"
#include "protocol/wire_requests.h"
#include "tests/service/service_process.h"

namespace {

using gc::protocol::Calculation;
using gc::protocol::check_dds;
using gc::protocol::Entity;
using Clock = std::chrono::steady_clock;

/// Requests on the bare C API: jam angles from made-up ids, or tooth contacts from a deaf client.
class RawSender {
 public:
  RawSender(int domain, std::uint64_t instance, bool deaf)
      : instance_(instance),
        participant_(check_dds(dds_create_participant(domain, nullptr, nullptr), "participant")),
        requests_(gc::protocol::make_request_topics(participant_.get())),
        replies_(gc::protocol::make_reply_topics(participant_.get())) {
    const std::size_t i = gc::protocol::index_of(deaf ? Calculation::kToothContact
                                                      : Calculation::kJamAngle);
    const gc::protocol::Qos qos = gc::protocol::request_reply_qos(0.1);
    const gc::protocol::Qos out =
        gc::protocol::partition_qos(gc::protocol::request_partition(instance));
    publisher_ = Entity(check_dds(dds_create_publisher(participant_.get(), out.get(), nullptr), "pub"));
    writer_ = Entity(check_dds(
        dds_create_writer(publisher_.get(), requests_[i].get(), qos.get(), nullptr), "writer"));
    if (!deaf) return;
    const gc::protocol::Qos in =
        gc::protocol::partition_qos(gc::protocol::reply_partition(client_id_));
    subscriber_ = Entity(check_dds(dds_create_subscriber(participant_.get(), in.get(), nullptr), "sub"));
    dds_qset_resource_limits(qos.get(), 100, DDS_LENGTH_UNLIMITED, DDS_LENGTH_UNLIMITED);
    reader_ = Entity(check_dds(
        dds_create_reader(subscriber_.get(), replies_[i].get(), qos.get(), nullptr), "reader"));
  }

  /// Rule 4 of docs/protocol.md, as far as this client follows it.
  bool wait_ready() {
    return gc::protocol::wait_until(
        [&] {
          return gc::protocol::matched_reader_count(writer_.get()) > 0 &&
                 (!reader_ || gc::protocol::matched_with_tagged_writer(
                                  reader_.get(), gc::protocol::hex_id(instance_)));
        },
        Clock::now() + std::chrono::seconds(20));
  }

  /// `count` requests for nrel_upwind: the deaf client's own tooth contacts, or jam angles each
  /// from a made-up id. A write that times out is not retried.
  void send(int count) {
    for (int k = 0; k < count; ++k) {
      if (reader_) {
        gc::protocol::OwnedSample<gearcoupling_ToothContactRequest> request(
            gearcoupling_ToothContactRequest_desc);
        gc::protocol::to_wire(gc::protocol::ToothContactRequest{
                                  gc::protocol::CatalogueName{"nrel_upwind"},
                                  gc::OperatingPoint{1.5e6, 0.007, 0.0, 0.1}, {}},
                              request.get());
        request.get().correlation = {client_id_, ++sequence_};
        dds_write(writer_.get(), &request.get());
        continue;
      }
      std::string name = "nrel_upwind";
      gearcoupling_JamAngleRequest request{};
      request.correlation = {sequence_ == 0 ? 0 : gc::protocol::random_id(), ++sequence_};
      request.coupling._d = gearcoupling_COUPLING_FROM_CATALOGUE;
      request.coupling._u.catalogue_name = name.data();
      dds_write(writer_.get(), &request);
    }
  }

 private:
  std::uint64_t instance_;
  std::uint64_t client_id_ = gc::protocol::random_id();
  std::uint64_t sequence_ = 0;
  Entity participant_;
  std::array<Entity, gc::protocol::kCalculationCount> requests_;
  std::array<Entity, gc::protocol::kCalculationCount> replies_;
  Entity publisher_;
  Entity subscriber_;
  Entity writer_;
  Entity reader_;
};

/// The id of an instance serving jam angles on `domain`, 0 if none within 20 s.
std::uint64_t find_instance(int domain) {
  gc::client::Client client({domain, std::chrono::seconds(20)});
  if (!client.wait_for_service(Calculation::kJamAngle, std::chrono::seconds(20))) return 0;
  const auto instances = client.instances();
  return instances.empty() ? 0 : instances.front().id;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 4) return 2;
  const int domain = std::atoi(argv[1]);
  const std::string mode = argv[2];
  const double seconds = std::atof(argv[3]);
  if ((mode != "fake-ids" && mode != "deaf") || !(seconds > 0.0 && seconds <= 600.0)) return 2;
  gc::test::use_loopback_config();
  const std::uint64_t instance = find_instance(domain);
  if (instance == 0) return 3;
  const bool deaf = mode == "deaf";
  RawSender sender(domain, instance, deaf);
  if (!sender.wait_ready()) return 3;
  const Clock::time_point end =
      Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(seconds));
  while (Clock::now() < end) {
    sender.send(deaf ? 10 : 1);
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  if (deaf) {
    std::this_thread::sleep_for(std::chrono::seconds(8));  // matched, full, silent
    _exit(0);  // deleting a reader whose delivery is stalled could wait: leave as a crash would
  }
  sender.send(1100);  // beyond the 1024 requests an instance parks
  return 0;
}
