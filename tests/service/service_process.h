// A gearcoupling-service child process for the tests: started with the loopback Cyclone
// configuration on the test's own domain, stopped by signal.
#pragma once

#include <sys/types.h>

#include <string>
#include <utility>
#include <vector>

namespace gc::test {

/// The DDS domain of this test process, 1-200 (ports stay in range): the first from
/// 1 + pid % 200 on that no other test process or its orphaned children hold (a lock file each,
/// held for the process's life and inherited by its children), so tests running in parallel
/// (one process each under ctest) never share a domain. Claimed on the first call; call it
/// before forking a child that joins the domain.
int test_domain();

/// Claims the first domain from 1 + first on (mod 200, 1-200) that no other process holds, for
/// the rest of this process's life and its children's; test_domain() with first = pid % 200.
int claim_test_domain_from(int first);

/// Moves the calling process into the network namespace /run/netns/<name>; false on failure.
/// Call in a child before it creates any DDS entity.
bool enter_network_namespace(const std::string& name);

/// Points CYCLONEDDS_URI at deploy/cyclonedds-loopback.xml (lo only, no multicast, peer
/// 127.0.0.1). Call before any DDS entity is created.
void use_loopback_config();

/// A child process of a test: a program run with `args` (args[0] its path), its standard error
/// (and with `capture_stdout` its standard output) in `log_path` when one is given, else the
/// test's. `environment` is set in the child only (e.g. a secure CYCLONEDDS_URI). With
/// `network_namespace`, the process runs in that namespace (/run/netns/<name>, as `ip netns`
/// makes them: a test "host").
class ChildProcess {
 public:
  explicit ChildProcess(std::vector<std::string> args, std::string log_path = {},
                        std::vector<std::pair<std::string, std::string>> environment = {},
                        std::string network_namespace = {}, bool capture_stdout = false);
  /// SIGKILLs the process if still running.
  ~ChildProcess();
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  /// Sends `signal`; for SIGKILL also waits for the process, for SIGSTOP until it has stopped
  /// (false if it did not within 10 s).
  bool signal(int signal);
  /// Waits (at most `timeout_s`) for the process to exit; its exit status, or -1 on timeout
  /// (then it is SIGKILLed).
  int wait_exit(double timeout_s);
  /// True while the process runs.
  bool running();
  pid_t pid() const { return pid_; }

 private:
  /// Waits (at most `timeout_s`) until every thread of the process has stopped; whether it has.
  bool wait_stopped(double timeout_s);

  pid_t pid_ = -1;
  bool reaped_ = false;
  int status_ = 0;
};

class ServiceProcess : public ChildProcess {
 public:
  /// Starts gearcoupling-service --domain test_domain() with `extra_args` (ChildProcess for the
  /// rest).
  explicit ServiceProcess(std::vector<std::string> extra_args = {}, std::string log_path = {},
                          std::vector<std::pair<std::string, std::string>> environment = {},
                          std::string network_namespace = {});
};

}  // namespace gc::test
