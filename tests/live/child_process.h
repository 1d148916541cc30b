// A child process of a live test (gearcoupling-monitor, gearcoupling record): started with its
// standard output and error in a file, stopped by signal. The environment (CYCLONEDDS_URI) is
// the test's.
#pragma once

#include <sys/types.h>

#include <string>
#include <vector>

namespace gc::test {

class ChildProcess {
 public:
  /// Runs `args` (args[0] the program's path), standard output and error to `log_path`.
  ChildProcess(std::vector<std::string> args, const std::string& log_path);
  /// SIGKILLs the process if still running.
  ~ChildProcess();
  ChildProcess(const ChildProcess&) = delete;
  ChildProcess& operator=(const ChildProcess&) = delete;

  void signal(int signal);
  /// Waits at most `timeout_s` for the exit; the exit code, or -1 (then SIGKILLs it).
  int wait_exit(double timeout_s);
  bool running();

 private:
  pid_t pid_ = -1;
  bool reaped_ = false;
  int status_ = 0;
};

}  // namespace gc::test
