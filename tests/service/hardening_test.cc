// Issue 9, bounded work per request, end to end: a request over the per-calculation deadline gets
// STATUS_DEADLINE_EXCEEDED, a 10 MB name is neither echoed nor logged whole; and what
// docs/protocol.md states of bad enum values and USER_DATA.
#include <signal.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <optional>
#include <sstream>

#include <gtest/gtest.h>

#include "client/client.h"
#include "codec/coupling_catalog.h"
#include "protocol/calculation_traits.h"
#include "protocol/matching.h"
#include "protocol/names.h"
#include "protocol/qos.h"
#include "protocol/random_id.h"
#include "protocol/reply_status.h"
#include "protocol/samples.h"
#include "protocol/topics.h"
#include "protocol/wire_inputs.h"
#include "tests/service/scaled_coupling.h"
#include "tests/service/read_text.h"
#include "tests/service/service_process.h"

namespace gc {
namespace {

using protocol::Calculation;
using protocol::CatalogueName;
using protocol::check_dds;
using protocol::Entity;
using Clock = std::chrono::steady_clock;

/// The largest coupling a request may carry inline (teeth = 10,000, the core's limit).
CouplingDefinition largest_inline_coupling() { return test::scaled_coupling(10000); }

/// The costliest tooth-contact request the ranges allow: the largest coupling, the most
/// iterations, the tightest tolerance.
protocol::ToothContactRequest costliest_request() {
  const CouplingDefinition d = largest_inline_coupling();
  const double jam = CouplingGeometry(d).jam_angle().angle_rad;
  ContactOptions options;
  options.load_sharing.max_iterations = kMaxLoadSharingIterations;
  options.load_sharing.tolerance = kMinLoadSharingTolerance;
  options.slices = 1000;
  // 100 times the teeth on 100 times the radius: 1e4 times the torque for nrel_upwind's tooth
  // loads at 2 MN m.
  return {d, OperatingPoint{2.0e10, 0.5 * jam, 0.0, 0.1}, options};
}

TEST(Deadline, ATinyDeadlineAnswersDeadlineExceededAndTheServiceKeepsServing) {
  test::ServiceProcess service({"--deadline-s", "1e-6"});
  client::Client client({test::test_domain(), std::chrono::seconds(20)});
  try {
    client.call<Calculation::kToothContact>(costliest_request());
    ADD_FAILURE() << "answered within a microsecond";
  } catch (const protocol::ServiceError& e) {
    EXPECT_EQ(e.status(), gearcoupling_STATUS_DEADLINE_EXCEEDED);
    EXPECT_EQ(e.field(), "");
    EXPECT_NE(std::string(e.what()).find("deadline of 1e-06 s"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(service.running());
  EXPECT_EQ(client.counters().timeouts, 0u);  // answered, not left to time out
}

TEST(Deadline, TheDefaultDeadlineAnswersTheCostliestAllowedRequest) {
  test::ServiceProcess service;
  client::Client client({test::test_domain(), std::chrono::seconds(20)});
  const protocol::ToothContactRequest request = costliest_request();
  const ToothContact remote = client.call<Calculation::kToothContact>(request);
  const ToothContact local =
      tooth_contact(CouplingGeometry(std::get<CouplingDefinition>(request.coupling)),
                    request.operating_point, request.options);
  EXPECT_EQ(remote.teeth.size(), 10000u);
  EXPECT_EQ(remote.load_sharing.q, local.load_sharing.q);
  EXPECT_EQ(remote.max_tooth_load_n, local.max_tooth_load_n);
}

TEST(Echo, ATenMegabyteNameIsRejectedWithoutEchoingOrLoggingItWhole) {
  const std::string log = "/tmp/gc_hardening_log_" + std::to_string(getpid()) + ".txt";
  test::ServiceProcess service({}, log);
  client::Client client({test::test_domain(), std::chrono::seconds(30)});
  const std::string huge(10u << 20, 'a');
  for (int r = 0; r < 3; ++r) {
    try {
      client.call<Calculation::kJamAngle>({CatalogueName{huge}});
      ADD_FAILURE() << "accepted";
    } catch (const InvalidInput& e) {
      EXPECT_EQ(e.field(), "coupling.catalogue_name");
      EXPECT_LE(std::string(e.what()).size(), protocol::kMaxEchoBytes);
      EXPECT_NE(std::string(e.what()).find("10485760 bytes in all"), std::string::npos)
          << e.what();
    }
  }
  // A name within the limit but unknown is echoed whole, with the names the instance knows.
  const std::string unknown(200, 'u');
  try {
    client.call<Calculation::kJamAngle>({CatalogueName{unknown}});
    ADD_FAILURE() << "accepted";
  } catch (const protocol::ServiceError& e) {
    EXPECT_EQ(e.status(), gearcoupling_STATUS_UNKNOWN_COUPLING);
    EXPECT_NE(std::string(e.what()).find(unknown), std::string::npos);
  }
  EXPECT_NO_THROW(client.call<Calculation::kJamAngle>({CatalogueName{"nrel_upwind"}}));
  service.signal(SIGTERM);
  EXPECT_EQ(service.wait_exit(10.0), 0);
  const std::string text = test::read_text(log);
  std::remove(log.c_str());
  EXPECT_NE(text.find("coupling.catalogue_name"), std::string::npos) << text;  // logged ...
  EXPECT_LT(text.size(), 16u << 10) << "the log grew by the names";           // ... but short
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    EXPECT_LT(line.size(), 2 * protocol::kMaxEchoBytes + 200) << line.substr(0, 200);
  }
}

/// A jam-angle client written on the bare C API, to send what the C++ client never would.
class RawJamAngleClient {
 public:
  explicit RawJamAngleClient(std::uint64_t instance)
      : instance_(instance),
        participant_(check_dds(dds_create_participant(test::test_domain(), nullptr, nullptr),
                               "dds_create_participant")),
        requests_(protocol::make_request_topics(participant_.get())),
        replies_(protocol::make_reply_topics(participant_.get())) {
    const std::size_t i = protocol::index_of(Calculation::kJamAngle);
    const protocol::Qos qos = protocol::request_reply_qos();
    const protocol::Qos out = protocol::partition_qos(protocol::request_partition(instance));
    const protocol::Qos in = protocol::partition_qos(protocol::reply_partition(client_id_));
    publisher_ = Entity(check_dds(dds_create_publisher(participant_.get(), out.get(), nullptr), "pub"));
    subscriber_ = Entity(check_dds(dds_create_subscriber(participant_.get(), in.get(), nullptr), "sub"));
    writer_ = Entity(check_dds(
        dds_create_writer(publisher_.get(), requests_[i].get(), qos.get(), nullptr), "writer"));
    reader_ = Entity(check_dds(
        dds_create_reader(subscriber_.get(), replies_[i].get(), qos.get(), nullptr), "reader"));
  }

  /// Rule 4 of docs/protocol.md: the request reader and the instance's reply writer matched.
  bool wait_ready() {
    return protocol::wait_until(
        [&] {
          return protocol::matched_reader_count(writer_.get()) > 0 &&
                 protocol::matched_with_tagged_writer(reader_.get(), protocol::hex_id(instance_));
        },
        Clock::now() + std::chrono::seconds(10));
  }

  /// Writes a catalogue request for nrel_upwind with the union discriminator `source`; what
  /// dds_write returns.
  dds_return_t try_send(std::uint64_t sequence, std::int32_t source) {
    std::string name = "nrel_upwind";
    gearcoupling_JamAngleRequest request{};
    request.correlation = {client_id_, sequence};
    request.coupling._d = static_cast<gearcoupling_CouplingSource>(source);
    request.coupling._u.catalogue_name = name.data();
    return dds_write(writer_.get(), &request);
  }
  void send(std::uint64_t sequence, std::int32_t source) {
    check_dds(try_send(sequence, source), "dds_write");
  }


  /// The status of the reply to `sequence`, if one comes within `wait`.
  std::optional<gearcoupling_ReplyStatus> reply_status(std::uint64_t sequence,
                                                       std::chrono::milliseconds wait) {
    std::optional<gearcoupling_ReplyStatus> status;
    protocol::wait_until(
        [&] {
          protocol::LoanedSamples<gearcoupling_JamAngleReply> samples(reader_.get());
          for (std::size_t k = 0; k < samples.size(); ++k) {
            if (samples.info(k).valid_data &&
                samples[k].correlation.sequence_number == sequence) {
              status = samples[k].status;
            }
          }
          return status.has_value();
        },
        Clock::now() + wait);
    return status;
  }

  /// The USER_DATA of every reply writer matched with this client's reader.
  std::vector<std::string> matched_user_data() {
    std::vector<dds_instance_handle_t> handles(16);
    const dds_return_t n = dds_get_matched_publications(reader_.get(), handles.data(), handles.size());
    std::vector<std::string> out;
    for (dds_return_t k = 0; k < n; ++k) {
      dds_builtintopic_endpoint_t* endpoint = dds_get_matched_publication_data(reader_.get(), handles[k]);
      void* value = nullptr;
      size_t size = 0;
      if (endpoint != nullptr && dds_qget_userdata(endpoint->qos, &value, &size)) {
        out.emplace_back(static_cast<const char*>(value), size);  // exactly `size` bytes
        dds_free(value);
      }
      dds_builtintopic_free_endpoint(endpoint);
    }
    return out;
  }

 private:
  std::uint64_t instance_;
  std::uint64_t client_id_ = protocol::random_id();
  Entity participant_;
  std::array<Entity, gc::protocol::kCalculationCount> requests_;
  std::array<Entity, gc::protocol::kCalculationCount> replies_;
  Entity publisher_;
  Entity subscriber_;
  Entity writer_;
  Entity reader_;
};

/// The id of the one instance on this test's domain.
std::uint64_t instance_id() {
  client::Client client({test::test_domain(), std::chrono::seconds(10)});
  EXPECT_TRUE(client.wait_for_service(Calculation::kJamAngle, std::chrono::seconds(10)));
  const std::vector<client::InstanceInfo> instances = client.instances();
  return instances.empty() ? 0 : instances.front().id;
}

TEST(Wire, ABadEnumValueCannotBeWritten) {
  // What a client sees for an enum (or union discriminator) value outside the IDL's: Cyclone's
  // dds_write refuses it (DDS_RETCODE_BAD_PARAMETER), nothing is sent, and the service, which
  // never sees it, carries on (docs/protocol.md, "Bad enum values").
  test::ServiceProcess service;
  const std::uint64_t instance = instance_id();
  ASSERT_NE(instance, 0u);
  RawJamAngleClient raw(instance);
  ASSERT_TRUE(raw.wait_ready());
  raw.send(1, gearcoupling_COUPLING_FROM_CATALOGUE);  // the control: the channel works
  EXPECT_EQ(raw.reply_status(1, std::chrono::seconds(10)), gearcoupling_STATUS_OK);
  EXPECT_EQ(raw.try_send(2, 7), DDS_RETCODE_BAD_PARAMETER);  // CouplingSource has 0 and 1 only

  raw.send(3, gearcoupling_COUPLING_FROM_CATALOGUE);  // the service carries on
  EXPECT_EQ(raw.reply_status(3, std::chrono::seconds(10)), gearcoupling_STATUS_OK);
}

TEST(Wire, ReplyWriterUserDataIsTheInstanceIdIn16HexDigitsWithoutNul) {
  test::ServiceProcess service;
  const std::uint64_t instance = instance_id();
  ASSERT_NE(instance, 0u);
  RawJamAngleClient raw(instance);
  ASSERT_TRUE(raw.wait_ready());
  const std::vector<std::string> user_data = raw.matched_user_data();
  ASSERT_EQ(user_data.size(), 1u);
  EXPECT_EQ(user_data.front().size(), 16u);  // no terminating NUL on the wire
  EXPECT_EQ(user_data.front(), protocol::hex_id(instance));
}

}  // namespace
}  // namespace gc
