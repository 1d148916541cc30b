// What anyone who can read the network sees of a round trip (docs/security.md's threat model): a
// packet socket on loopback keeps every UDP datagram sent to the test's
// domain while a client calls the service. In plain mode the request's coupling name, the
// reply's error text and the topic names are there to read; under DDS Security none of them is.
// The plain run is the control: it shows the capture sees what the secure run must hide.
#include <arpa/inet.h>
#include <linux/if_packet.h>
#include <net/ethernet.h>
#include <net/if.h>
#include <netinet/ip.h>
#include <netinet/udp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstddef>
#include <chrono>
#include <cstring>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include <gtest/gtest.h>

#include "client/client.h"
#include "tests/service/secure_cell.h"
#include "tests/service/secure_cell_test.h"
#include "tests/service/service_process.h"

namespace gc {
namespace {

using protocol::Calculation;
using protocol::CatalogueName;

constexpr int kClientDomain = 214;  // client-a's local domain id (test_domain() on the wire)
// A coupling no catalogue has: the request carries it, the error reply names the catalogue.
constexpr const char* kRequestMarker = "wiretap-marker-7f3a";
constexpr const char* kReplyMarker = "is not in the service's catalogue";
constexpr const char* kTopicMarker = "gearcoupling/jam_angle/request";

/// Every UDP payload sent on loopback to a port of `domain` (Cyclone's 7400 + 250 * domain and
/// the 250 ports above), from construction until destruction. A packet socket needs
/// CAP_NET_RAW: available() says whether it got one.
class LoopbackCapture {
 public:
  explicit LoopbackCapture(int domain)
      : first_port_(7400 + 250 * domain), fd_(socket(AF_PACKET, SOCK_DGRAM, htons(ETH_P_IP))) {
    if (fd_ < 0) {
      error_ = std::strerror(errno);
      return;
    }
    sockaddr_ll lo{};
    lo.sll_family = AF_PACKET;
    lo.sll_protocol = htons(ETH_P_IP);
    lo.sll_ifindex = static_cast<int>(if_nametoindex("lo"));
    if (lo.sll_ifindex == 0 || bind(fd_, reinterpret_cast<sockaddr*>(&lo), sizeof lo) != 0) {
      error_ = std::strerror(errno);
      close(fd_);
      fd_ = -1;
      return;
    }
    reader_ = std::thread([this] { read_until_stopped(); });
  }
  ~LoopbackCapture() {
    stop_ = true;
    if (reader_.joinable()) reader_.join();
    if (fd_ >= 0) close(fd_);
  }
  LoopbackCapture(const LoopbackCapture&) = delete;
  LoopbackCapture& operator=(const LoopbackCapture&) = delete;

  bool available() const { return fd_ >= 0; }
  /// Why not available().
  const std::string& error() const { return error_; }
  std::string payloads() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return payloads_;
  }

 private:
  void read_until_stopped() {
    unsigned char packet[65536];
    while (!stop_) {
      pollfd ready{fd_, POLLIN, 0};
      if (poll(&ready, 1, 50) <= 0) continue;
      const ssize_t n = recv(fd_, packet, sizeof packet, 0);
      if (n < static_cast<ssize_t>(sizeof(iphdr))) continue;
      const auto* ip = reinterpret_cast<const iphdr*>(packet);
      const std::size_t ip_length = ip->ihl * 4u;
      if (ip->protocol != IPPROTO_UDP || static_cast<std::size_t>(n) < ip_length + sizeof(udphdr)) continue;
      const auto* udp = reinterpret_cast<const udphdr*>(packet + ip_length);
      const int port = ntohs(udp->dest);
      if (port < first_port_ || port >= first_port_ + 250) continue;
      const std::size_t start = ip_length + sizeof(udphdr);
      std::lock_guard<std::mutex> lock(mutex_);
      payloads_.append(reinterpret_cast<const char*>(packet + start), static_cast<std::size_t>(n) - start);
    }
  }

  const int first_port_;
  int fd_;
  std::string error_;
  std::atomic<bool> stop_{false};
  mutable std::mutex mutex_;
  std::string payloads_;
  std::thread reader_;
};

bool contains(const std::string& bytes, const char* text) { return bytes.find(text) != std::string::npos; }

/// Calls the service for the marker coupling (an error reply) and for a real one, as `client`.
void call_with_markers(client::Client& client) {
  EXPECT_ANY_THROW(client.call<Calculation::kJamAngle>({CatalogueName{kRequestMarker}}));
  EXPECT_GT(client.call<Calculation::kJamAngle>({CatalogueName{"nrel_upwind"}}).jam.angle_rad, 0.0);
}

TEST(OnTheWire, APlainRoundTripIsReadableByAnyoneOnTheNetwork) {
  LoopbackCapture capture(test::test_domain());
  if (!capture.available()) GTEST_SKIP() << "no packet socket on lo (needs CAP_NET_RAW): " << capture.error();
  test::ServiceProcess service;
  client::Client client({test::test_domain(), std::chrono::seconds(30)});
  call_with_markers(client);
  std::this_thread::sleep_for(std::chrono::milliseconds(200));  // the capture thread's last reads
  const std::string seen = capture.payloads();
  EXPECT_TRUE(contains(seen, kRequestMarker));
  EXPECT_TRUE(contains(seen, kReplyMarker));
  EXPECT_TRUE(contains(seen, kTopicMarker));
}

class OnTheWireSecure : public test::SecureCellTest {
 protected:
  void SetUp() override { make_cell(); }
};

TEST_F(OnTheWireSecure, NothingOfASecureRoundTripOrItsDiscoveryIsReadable) {
  LoopbackCapture capture(test::test_domain());
  if (!capture.available()) GTEST_SKIP() << "no packet socket on lo (needs CAP_NET_RAW): " << capture.error();
  test::ServiceProcess service({}, {}, {{"CYCLONEDDS_URI", cell_->uri("service-main")}});
  const test::LocalDomain domain(kClientDomain, cell_->uri("client-a"));
  client::Client client({kClientDomain, std::chrono::seconds(30), cell_->client_prefix("a")});
  call_with_markers(client);
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  const std::string seen = capture.payloads();
  EXPECT_GT(seen.size(), 1000u);  // the round trips and the discovery went by the capture
  EXPECT_FALSE(contains(seen, kRequestMarker));
  EXPECT_FALSE(contains(seen, kReplyMarker));
  EXPECT_FALSE(contains(seen, kTopicMarker));
}

}  // namespace
}  // namespace gc
