// Test hosts on one LAN (issues 9 and 26): three network namespaces joined by a bridge in a
// fourth, addressed in 198.18.0.0/15 (the range reserved for network benchmarks), nothing of it
// in the test machine's own network namespace. Each host is joined to the bridge either by a
// veth pair, or by a user-space faulty link (tests/service/faulty_link.cc between two TAP
// devices), whose faults are set per host and which can be cut and healed while the test runs.
// Needs root (ip netns, /dev/net/tun); why_not() says why when the network could not be built.
// The namespaces, the links and everything in them are removed when the object is.
#pragma once

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "tests/service/link_faults.h"
#include "tests/service/service_process.h"

namespace gc::test {

/// Runs a command quietly; its exit status, or -1 when it could not run.
int run_quietly(const std::vector<std::string>& command);

class TestNetwork {
 public:
  static constexpr int kHosts = 3;

  /// Hosts 1..3 joined to the bridge by veth pairs.
  TestNetwork();
  /// Host i joined to the bridge through a faulty link with faults[i - 1].
  explicit TestNetwork(const std::array<LinkFaults, kHosts>& faults);
  ~TestNetwork();
  TestNetwork(const TestNetwork&) = delete;
  TestNetwork& operator=(const TestNetwork&) = delete;

  /// Empty when the network is up, else why not.
  const std::string& why_not() const { return why_not_; }
  /// Host i's namespace (gch<i>-<pid>); its interface eth0 has address(i)/24.
  std::string host(int i) const { return "gch" + std::to_string(i) + "-" + suffix_; }
  static std::string address(int i) { return "198.18.0." + std::to_string(i); }

  /// Cuts host i's faulty link (every frame both ways dropped) / heals it.
  void partition(int i);
  void heal(int i);
  /// Stops host i's faulty link and returns what it did, per direction (its counts).
  std::string stop_link(int i);

 private:
  std::string switch_name() const { return "gcsw-" + suffix_; }
  /// Root, capabilities, iproute2, the bridge: false (why_not_ set) when one is missing.
  bool build_switch();
  bool in_switch(std::vector<std::string> args) const;
  bool in_host(int i, std::vector<std::string> args) const;
  bool add_host(int i);
  /// Host i's eth0 and its switch port p<i>: a veth pair, or two TAPs and a faulty link.
  bool add_veth(int i);
  bool add_faulty_link(int i, const LinkFaults& faults);
  std::string link_log(int i) const;

  std::string suffix_;
  std::vector<std::string> created_;
  std::array<std::unique_ptr<ChildProcess>, kHosts> links_;
  std::string why_not_;
};

}  // namespace gc::test
