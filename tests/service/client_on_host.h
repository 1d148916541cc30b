// A client process on a test host (tests/service/test_network.h): a forked child that enters
// the host's network namespace, sets its environment, and only then creates its DDS
// participant; it reports to the test in lines on a pipe.
#pragma once

#include <sys/types.h>

#include <chrono>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace gc::test {

/// The next line from `fd` within `timeout` (`buffer` keeps what came after it); empty on
/// timeout or end of file.
std::string read_line(int fd, std::chrono::milliseconds timeout, std::string& buffer);

class ClientOnHost {
 public:
  using Say = std::function<void(const std::string&)>;

  /// Runs `work` in the child; its result is the child's last line ("error <what>" if it throws).
  ClientOnHost(const std::string& host, std::vector<std::pair<std::string, std::string>> environment,
               const std::function<std::string(const Say&)>& work);
  /// SIGKILLs the child if still running.
  ~ClientOnHost();
  ClientOnHost(const ClientOnHost&) = delete;
  ClientOnHost& operator=(const ClientOnHost&) = delete;

  /// Its next line within `timeout`; empty when none came.
  std::string line(std::chrono::milliseconds timeout) { return read_line(fd_, timeout, buffer_); }
  /// Sends `signal` to the child.
  void signal(int signal) const;

 private:
  pid_t pid_ = -1;
  int fd_ = -1;
  std::string buffer_;
};

}  // namespace gc::test
