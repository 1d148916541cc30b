#include "tests/service/test_network.h"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <thread>

namespace gc::test {
namespace {

/// The effective capability set of this process (/proc/self/status, CapEff).
unsigned long long effective_capabilities() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);) {
    if (line.rfind("CapEff:", 0) == 0) return std::stoull(line.substr(7), nullptr, 16);
  }
  return 0;
}

constexpr int kCapNetAdmin = 12;
constexpr int kCapSysAdmin = 21;

std::string read_file(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// Host i's port on the switch, p<i>.
std::string port_name(int i) {
  std::string port = "p";
  port += std::to_string(i);  // not "p" + ...: GCC 12 warns (-Wrestrict) on it, wrongly
  return port;
}

std::string format_faults(const LinkFaults& f) {
  std::ostringstream text;
  text << "loss " << f.loss << ", delay " << f.delay_s << " s +- " << f.jitter_s << " s, duplicate " << f.duplicate
       << ", reorder " << f.reorder;
  return text.str();
}

}  // namespace

int run_quietly(const std::vector<std::string>& command) {
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

TestNetwork::TestNetwork() : suffix_(std::to_string(getpid())) {
  if (!build_switch()) return;
  for (int i = 1; i <= kHosts; ++i) {
    if (!add_host(i) || !add_veth(i)) {
      why_not_ = "could not build the bridge and the veth pairs with ip(8)";
      return;
    }
  }
}

TestNetwork::TestNetwork(const std::array<LinkFaults, kHosts>& faults) : suffix_(std::to_string(getpid())) {
  if (access("/dev/net/tun", R_OK | W_OK) != 0) {
    why_not_ = "no /dev/net/tun here (TUN/TAP devices) for the faulty links";
    return;
  }
  if (!build_switch()) return;
  for (int i = 1; i <= kHosts; ++i) {
    if (!add_host(i) || !add_faulty_link(i, faults[i - 1])) {
      if (why_not_.empty()) why_not_ = "could not build the bridge, the TAP devices and the faulty links";
      return;
    }
  }
}

TestNetwork::~TestNetwork() {
  for (auto& link : links_) link.reset();  // SIGKILLs the forwarders still running
  for (int i = 1; i <= kHosts; ++i) std::filesystem::remove(link_log(i));
  for (const std::string& ns : created_) run_quietly({"ip", "netns", "del", ns});
}

bool TestNetwork::build_switch() {
  if (geteuid() != 0) {
    why_not_ = "needs root to create network namespaces (ip netns); uid is " + std::to_string(geteuid());
    return false;
  }
  const unsigned long long caps = effective_capabilities();
  if ((caps >> kCapNetAdmin & 1) == 0 || (caps >> kCapSysAdmin & 1) == 0) {
    why_not_ = "root without CAP_NET_ADMIN or CAP_SYS_ADMIN (a container's bounding set?): no network namespaces";
    return false;
  }
  if (run_quietly({"ip", "netns", "add", switch_name()}) != 0) {
    why_not_ = "ip netns add failed (no iproute2, or no permission for network namespaces here)";
    return false;
  }
  created_.push_back(switch_name());
  const bool built = in_switch({"link", "add", "br0", "type", "bridge"}) &&
                     // Flood multicast to every port: no querier on this bridge to teach snooping.
                     (in_switch({"link", "set", "br0", "type", "bridge", "mcast_snooping", "0"}), true) &&
                     in_switch({"link", "set", "br0", "up"});
  if (!built) why_not_ = "could not make the bridge with ip(8)";
  return built;
}

bool TestNetwork::in_switch(std::vector<std::string> args) const {
  args.insert(args.begin(), {"ip", "-n", switch_name()});
  return run_quietly(args) == 0;
}

bool TestNetwork::in_host(int i, std::vector<std::string> args) const {
  args.insert(args.begin(), {"ip", "-n", host(i)});
  return run_quietly(args) == 0;
}

bool TestNetwork::add_host(int i) {
  if (run_quietly({"ip", "netns", "add", host(i)}) != 0) return false;
  created_.push_back(host(i));
  return in_host(i, {"link", "set", "lo", "up"});
}

bool TestNetwork::add_veth(int i) {
  const std::string port = port_name(i);
  return in_switch({"link", "add", port, "type", "veth", "peer", "name", "eth0", "netns", host(i)}) &&
         in_switch({"link", "set", port, "master", "br0"}) && in_switch({"link", "set", port, "up"}) &&
         in_host(i, {"addr", "add", address(i) + "/24", "dev", "eth0"}) && in_host(i, {"link", "set", "eth0", "up"}) &&
         in_host(i, {"route", "add", "224.0.0.0/4", "dev", "eth0"});
}

std::string TestNetwork::link_log(int i) const {
  return (std::filesystem::temp_directory_path() / ("gc_faulty_link_" + suffix_ + "_" + std::to_string(i) + ".log"))
      .string();
}

bool TestNetwork::add_faulty_link(int i, const LinkFaults& faults) {
  const std::string port = port_name(i);
  const bool taps = in_switch({"tuntap", "add", "dev", port, "mode", "tap"}) &&
                    in_switch({"link", "set", port, "master", "br0"}) && in_switch({"link", "set", port, "up"}) &&
                    in_host(i, {"tuntap", "add", "dev", "eth0", "mode", "tap"}) &&
                    in_host(i, {"addr", "add", address(i) + "/24", "dev", "eth0"}) &&
                    in_host(i, {"link", "set", "eth0", "up"}) && in_host(i, {"route", "add", "224.0.0.0/4", "dev", "eth0"});
  if (!taps) return false;
  links_[i - 1] = std::make_unique<ChildProcess>(
      std::vector<std::string>{GC_FAULTY_LINK_BINARY, "--a", host(i) + ":eth0", "--b", switch_name() + ":" + port,
                               "--loss", std::to_string(faults.loss), "--delay-s", std::to_string(faults.delay_s),
                               "--jitter-s", std::to_string(faults.jitter_s), "--duplicate",
                               std::to_string(faults.duplicate), "--reorder", std::to_string(faults.reorder),
                               "--seed", std::to_string(1000 + i)},
      link_log(i));
  // Ready once both TAPs are attached (their carriers up) and it handles its signals.
  const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(10);
  while (read_file(link_log(i)).find("faulty_link: ready") == std::string::npos) {
    if (!links_[i - 1]->running() || std::chrono::steady_clock::now() > give_up) {
      why_not_ = "the faulty link of host " + std::to_string(i) + " (" + format_faults(faults) +
                 ") did not start: " + read_file(link_log(i));
      return false;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return true;
}

void TestNetwork::partition(int i) { links_.at(i - 1)->signal(SIGUSR1); }
void TestNetwork::heal(int i) { links_.at(i - 1)->signal(SIGUSR2); }

std::string TestNetwork::stop_link(int i) {
  links_.at(i - 1)->signal(SIGTERM);
  links_.at(i - 1)->wait_exit(5.0);
  const std::string log = read_file(link_log(i));
  const std::string ready = "faulty_link: ready\n";
  return log.rfind(ready, 0) == 0 ? log.substr(ready.size()) : log;
}

}  // namespace gc::test
