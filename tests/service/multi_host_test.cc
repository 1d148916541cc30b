// Several hosts (issue 9): three network namespaces joined by a bridge, addressed in 198.18.0.0/15
// (the range reserved for network benchmarks), with the LAN configuration's real multicast
// discovery instead of loopback. Two service instances run on two "hosts", a client on the third;
// one instance is killed mid-run and every request must still be answered exactly once, by the
// other. Needs root (ip netns); skipped with a message otherwise. The namespaces and everything
// in them are removed when the test ends.
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <deque>
#include <functional>
#include <future>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "clients/remote/client.h"
#include "codec/coupling_catalog.h"
#include "core/induced_moments.h"
#include "protocol/matching.h"
#include "tests/service/identical.h"
#include "tests/service/secure_cell.h"
#include "tests/service/service_process.h"

namespace gc {
namespace {

using protocol::Calculation;
using protocol::CatalogueName;
using Clock = std::chrono::steady_clock;

/// Runs a command quietly; its exit status, or -1 when it could not run.
int run(const std::vector<std::string>& command) {
  std::cout.flush();  // else the child's freopen writes the parent's unflushed output again
  std::fflush(nullptr);
  const pid_t pid = fork();
  if (pid < 0) return -1;
  if (pid == 0) {
    std::freopen("/dev/null", "w", stdout);
    std::freopen("/dev/null", "w", stderr);
    std::vector<char*> argv;
    for (const std::string& a : command) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    execvp(argv[0], argv.data());
    _exit(127);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

/// Hosts 1..3 (namespaces gch<i>-<pid>, interface eth0 at 198.18.0.<i>/24) on a bridge in a
/// fourth namespace: nothing of it in the test machine's own network namespace.
class TestNetwork {
 public:
  static constexpr int kHosts = 3;

  TestNetwork() : suffix_(std::to_string(getpid())) {
    if (geteuid() != 0) {
      why_not_ = "needs root to create network namespaces (ip netns)";
      return;
    }
    if (run({"ip", "netns", "add", switch_name()}) != 0) {
      why_not_ = "ip netns add failed (no iproute2, or no permission for network namespaces here)";
      return;
    }
    created_.push_back(switch_name());
    const bool built = in_switch({"link", "add", "br0", "type", "bridge"}) &&
                       // Flood multicast to every port: no querier on this bridge to teach snooping.
                       (in_switch({"link", "set", "br0", "type", "bridge", "mcast_snooping", "0"}), true) &&
                       in_switch({"link", "set", "br0", "up"}) && add_hosts();
    if (!built) why_not_ = "could not build the bridge and the veth pairs with ip(8)";
  }

  ~TestNetwork() {
    for (const std::string& ns : created_) run({"ip", "netns", "del", ns});
  }

  /// Empty when the network is up, else why not.
  const std::string& why_not() const { return why_not_; }
  std::string host(int i) const { return "gch" + std::to_string(i) + "-" + suffix_; }
  static std::string address(int i) { return "198.18.0." + std::to_string(i); }

 private:
  std::string switch_name() const { return "gcsw-" + suffix_; }

  bool in_switch(std::vector<std::string> args) const {
    args.insert(args.begin(), {"ip", "-n", switch_name()});
    return run(args) == 0;
  }
  bool in_host(int i, std::vector<std::string> args) const {
    args.insert(args.begin(), {"ip", "-n", host(i)});
    return run(args) == 0;
  }

  bool add_hosts() {
    for (int i = 1; i <= kHosts; ++i) {
      if (run({"ip", "netns", "add", host(i)}) != 0) return false;
      created_.push_back(host(i));
      const std::string port = "p" + std::to_string(i);
      const bool ok = in_switch({"link", "add", port, "type", "veth", "peer", "name", "eth0", "netns", host(i)}) &&
                      in_switch({"link", "set", port, "master", "br0"}) && in_switch({"link", "set", port, "up"}) &&
                      in_host(i, {"addr", "add", address(i) + "/24", "dev", "eth0"}) &&
                      in_host(i, {"link", "set", "eth0", "up"}) && in_host(i, {"link", "set", "lo", "up"}) &&
                      in_host(i, {"route", "add", "224.0.0.0/4", "dev", "eth0"});
      if (!ok) return false;
    }
    return true;
  }

  std::string suffix_;
  std::vector<std::string> created_;
  std::string why_not_;
};

OperatingPoint unique_point(int request) { return {1.0e5 + 10.0 * request, 0.005, 0.3, 0.1}; }

constexpr const char* kLanMulticast = "file://" GC_SOURCE_DIR "/deploy/cyclonedds-lan-multicast.xml";

/// The next line from `fd` within `timeout`; empty on timeout or end of file.
std::string read_line(int fd, std::chrono::seconds timeout, std::string& buffer) {
  const Clock::time_point give_up = Clock::now() + timeout;
  for (;;) {
    if (const auto nl = buffer.find('\n'); nl != std::string::npos) {
      std::string line = buffer.substr(0, nl);
      buffer.erase(0, nl + 1);
      return line;
    }
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(give_up - Clock::now()).count();
    if (left <= 0) return "";
    pollfd p{fd, POLLIN, 0};
    if (poll(&p, 1, static_cast<int>(left)) <= 0) return "";
    char chunk[512];
    const ssize_t n = read(fd, chunk, sizeof chunk);
    if (n <= 0) return "";
    buffer.append(chunk, static_cast<std::size_t>(n));
  }
}

/// A client process on a test host: a forked child that enters the host's namespace, sets its
/// environment, and only then creates its participant; it reports in lines on a pipe.
class ClientOnHost {
 public:
  using Say = std::function<void(const std::string&)>;

  ClientOnHost(const std::string& host, std::vector<std::pair<std::string, std::string>> environment,
               const std::function<std::string(const Say&)>& work) {
    int fds[2];
    if (pipe(fds) != 0) throw std::runtime_error("pipe failed");
    std::cout.flush();
    pid_ = fork();
    if (pid_ < 0) throw std::runtime_error("fork failed");
    if (pid_ == 0) {
      close(fds[0]);
      const Say say = [out = fds[1]](const std::string& line) {
        const std::string text = line + "\n";
        (void)!write(out, text.data(), text.size());
      };
      if (!test::enter_network_namespace(host)) {
        say("error cannot enter " + host);
        _exit(1);
      }
      for (const auto& [name, value] : environment) setenv(name.c_str(), value.c_str(), 1);
      try {
        say(work(say));
        _exit(0);
      } catch (const std::exception& e) {
        say(std::string("error ") + e.what());
        _exit(1);
      }
    }
    close(fds[1]);
    fd_ = fds[0];
  }
  ~ClientOnHost() {
    close(fd_);
    kill(pid_, SIGKILL);
    waitpid(pid_, nullptr, 0);
  }
  ClientOnHost(const ClientOnHost&) = delete;
  ClientOnHost& operator=(const ClientOnHost&) = delete;

  /// Its next line within `timeout`; empty when none came.
  std::string line(std::chrono::seconds timeout) { return read_line(fd_, timeout, buffer_); }

 private:
  pid_t pid_ = -1;
  int fd_ = -1;
  std::string buffer_;
};

/// What the client on host 3 saw.
struct ClientReport {
  std::size_t instances_at_start = 0;
  int answered = 0, wrong = 0, failed = 0;
  client::ClientCounters counters;
};

constexpr int kRequests = 1500;
constexpr std::size_t kWindow = 32;
constexpr int kKillAfter = kRequests / 3;

/// kRequests induced-moment requests, kWindow in flight, each checked against the core's value;
/// says "kill" when a third are answered.
std::string requests_with_a_kill(int domain, const std::function<void(const std::string&)>& say) {
  const auto catalogue = codec::load_coupling_catalog(codec::default_catalog_dir());
  const CouplingGeometry& coupling = catalogue.at("nrel_downwind");
  client::Client client({domain, std::chrono::seconds(20)});
  ClientReport r;
  protocol::wait_until([&] { return client.instances().size() == 2; }, Clock::now() + std::chrono::seconds(20));
  r.instances_at_start = client.instances().size();
  std::deque<std::pair<int, std::future<InducedMoments>>> in_flight;
  for (int sent = 0; sent < kRequests || !in_flight.empty();) {
    if (sent < kRequests && in_flight.size() < kWindow) {
      in_flight.emplace_back(sent, client.call_async<Calculation::kInducedMoments>(
                                       {CatalogueName{"nrel_downwind"}, unique_point(sent), {}}));
      ++sent;
      continue;
    }
    auto& [request, future] = in_flight.front();
    try {
      const InducedMoments remote = future.get();
      r.wrong += test::bits(remote.magnitude_nm) != test::bits(induced_moments(coupling, unique_point(request)).magnitude_nm);
      ++r.answered;
    } catch (const std::exception& e) {
      if (r.failed++ == 0) say(std::string("failure ") + e.what());
    }
    in_flight.pop_front();
    if (r.answered == kKillAfter) say("kill");
  }
  r.counters = client.counters();
  std::ostringstream line;
  line << "report " << r.instances_at_start << " " << r.answered << " " << r.wrong << " " << r.failed << " "
       << r.counters.sent << " " << r.counters.replies << " " << r.counters.resent << " " << r.counters.duplicates
       << " " << r.counters.timeouts << " " << r.counters.foreign;
  return line.str();
}

TEST(MultiHost, TwoInstancesOnTwoHostsOneKilledEveryRequestAnsweredExactlyOnceOnTheThird) {
  const TestNetwork network;
  if (!network.why_not().empty()) GTEST_SKIP() << network.why_not();
  setenv("CYCLONEDDS_URI", kLanMulticast, 1);
  const int domain = test::test_domain();
  test::ServiceProcess a({}, {}, {}, network.host(1));
  test::ServiceProcess b({}, {}, {}, network.host(2));
  ClientOnHost client(network.host(3), {}, [domain](const ClientOnHost::Say& say) { return requests_with_a_kill(domain, say); });

  std::string line = client.line(std::chrono::seconds(60));
  EXPECT_EQ(line, "kill") << "the client never got a third of its answers";
  if (line == "kill") {
    a.signal(SIGKILL);
    line = client.line(std::chrono::seconds(90));
  }
  std::istringstream report(line);
  std::string word;
  ClientReport r;
  report >> word >> r.instances_at_start >> r.answered >> r.wrong >> r.failed >> r.counters.sent >> r.counters.replies >>
      r.counters.resent >> r.counters.duplicates >> r.counters.timeouts >> r.counters.foreign;
  ASSERT_EQ(word, "report") << "the client said \"" << line << "\"";
  EXPECT_EQ(r.instances_at_start, 2u) << "both instances discovered across the bridge by multicast";
  EXPECT_EQ(r.answered, kRequests);
  EXPECT_EQ(r.failed, 0);
  EXPECT_EQ(r.wrong, 0);
  EXPECT_EQ(r.counters.replies, static_cast<std::uint64_t>(kRequests)) << "each request answered once";
  EXPECT_EQ(r.counters.duplicates, 0u);
  EXPECT_EQ(r.counters.foreign, 0u);
  EXPECT_EQ(r.counters.timeouts, 0u);
  EXPECT_GT(r.counters.resent, 0u) << "the killed instance's unanswered requests went to the other host";
  EXPECT_EQ(r.counters.sent, kRequests + r.counters.resent);
  EXPECT_TRUE(b.running());
  std::cout << "across hosts: " << kRequests << " requests, " << r.counters.resent
            << " resent to host 2 after host 1's instance was killed\n";
}

/// How many of `calls` jam-angle calls a client with `options` gets answered, after waiting up
/// to `discovery` for an instance: "answered <n> instances <m>".
std::string jam_angle_calls(client::ClientOptions options, int calls, std::chrono::seconds discovery) {
  client::Client client(options);
  const bool found = client.wait_for_service(Calculation::kJamAngle, discovery);
  int answered = 0;
  for (int c = 0; found && c < calls; ++c) {
    try {
      client.call<Calculation::kJamAngle>({CatalogueName{"nrel_upwind"}});
      ++answered;
    } catch (const std::exception&) {
    }
  }
  return "answered " + std::to_string(answered) + " instances " + std::to_string(client.instances().size());
}

// The secure configuration across hosts: the service on host 1 and a client with its certificate
// on host 3 talk over the bridge, authenticated and encrypted; a participant without
// certificates on host 2 finds no instance.
TEST(MultiHost, TheSecureConfigurationWorksAcrossHostsAndAStrangerOnTheLanSeesNothing) {
  if (!test::security_plugins_installed()) GTEST_SKIP() << "Cyclone's DDS Security plugins are not installed";
  const TestNetwork network;
  if (!network.why_not().empty()) GTEST_SKIP() << network.why_not();
  const test::SecureCell cell;
  const int domain = test::test_domain();
  test::ServiceProcess service({}, {}, {{"CYCLONEDDS_URI", cell.uri("service-main", kLanMulticast)}}, network.host(1));

  client::ClientOptions secure{domain, std::chrono::seconds(10)};
  secure.client_id_prefix = cell.client_prefix("a");
  ClientOnHost client(network.host(3), {{"CYCLONEDDS_URI", cell.uri("client-a", kLanMulticast)}},
                      [secure](const ClientOnHost::Say&) { return jam_angle_calls(secure, 50, std::chrono::seconds(20)); });
  ClientOnHost stranger(network.host(2), {{"CYCLONEDDS_URI", kLanMulticast}}, [domain](const ClientOnHost::Say&) {
    return jam_angle_calls({domain, std::chrono::seconds(2)}, 5, std::chrono::seconds(8));
  });
  EXPECT_EQ(client.line(std::chrono::seconds(60)), "answered 50 instances 1");
  EXPECT_EQ(stranger.line(std::chrono::seconds(60)), "answered 0 instances 0");
  EXPECT_TRUE(service.running());
}

}  // namespace
}  // namespace gc
