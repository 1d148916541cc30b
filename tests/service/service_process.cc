#include "tests/service/service_process.h"

#include <fcntl.h>
#include <sched.h>
#include <signal.h>
#include <sys/file.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <thread>

namespace gc::test {

// The claim is an exclusive flock on $TMPDIR/gearcoupling-test-domains/<id>, its descriptor kept
// open for the life of this process and inherited by its children (no O_CLOEXEC), so a service
// orphaned by a killed test still holds its domain. By pid alone, two concurrent tests or an
// orphan shared a domain once in 200 pids, and a stopped service's requests were then answered
// by the other's (tests/claim_domain.sh and tests/dashboard/domain_claim.py claim alike).
int claim_test_domain_from(int first) {
  std::error_code ignored;
  const auto dir = std::filesystem::temp_directory_path(ignored) / "gearcoupling-test-domains";
  std::filesystem::create_directories(dir, ignored);
  std::filesystem::permissions(dir, std::filesystem::perms::all | std::filesystem::perms::sticky_bit,
                               ignored);
  for (int i = 0; i < 200; ++i) {
    const int domain = 1 + (first + i) % 200;
    const int fd = open((dir / std::to_string(domain)).c_str(), O_RDWR | O_CREAT, 0666);
    if (fd < 0) continue;
    if (flock(fd, LOCK_EX | LOCK_NB) == 0) return domain;  // fd stays open: the claim
    close(fd);
  }
  return 1 + first;  // every domain held (or no temporary directory): the first, as before
}

int test_domain() {
  static const int domain = claim_test_domain_from(static_cast<int>(getpid() % 200));
  return domain;
}

void use_loopback_config() {
  setenv("CYCLONEDDS_URI", "file://" GC_SOURCE_DIR "/deploy/cyclonedds-loopback.xml", 1);
}

bool enter_network_namespace(const std::string& name) {
  const int fd = open(("/run/netns/" + name).c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return false;
  const bool entered = setns(fd, CLONE_NEWNET) == 0;
  close(fd);
  return entered;
}

namespace {

std::vector<std::string> service_args(std::vector<std::string> extra_args) {
  std::vector<std::string> args = {GC_SERVICE_BINARY, "--domain", std::to_string(test_domain()),
                                   "--log-level", "warn"};
  args.insert(args.end(), extra_args.begin(), extra_args.end());
  return args;
}

}  // namespace

ServiceProcess::ServiceProcess(std::vector<std::string> extra_args, std::string log_path,
                               std::vector<std::pair<std::string, std::string>> environment,
                               std::string network_namespace)
    : ChildProcess(service_args(std::move(extra_args)), std::move(log_path), std::move(environment),
                   std::move(network_namespace)) {}

ChildProcess::ChildProcess(std::vector<std::string> args, std::string log_path,
                           std::vector<std::pair<std::string, std::string>> environment,
                           std::string network_namespace, bool capture_stdout) {
  pid_ = fork();
  if (pid_ < 0) throw std::runtime_error("fork failed");
  if (pid_ == 0) {
    if (!network_namespace.empty() && !enter_network_namespace(network_namespace)) _exit(125);
    if (!log_path.empty()) {
      const int log = open(log_path.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      if (log < 0) _exit(126);
      dup2(log, STDERR_FILENO);
      if (capture_stdout) dup2(log, STDOUT_FILENO);
      close(log);
    }
    for (const auto& [name, value] : environment) setenv(name.c_str(), value.c_str(), 1);
    std::vector<char*> argv;
    for (std::string& arg : args) argv.push_back(arg.data());
    argv.push_back(nullptr);
    execv(argv[0], argv.data());
    _exit(127);
  }
}

ChildProcess::~ChildProcess() {
  if (running()) signal(SIGKILL);
}

bool ChildProcess::signal(int signal) {
  if (reaped_) return false;
  kill(pid_, signal);
  if (signal == SIGKILL) wait_exit(10.0);
  return signal == SIGSTOP ? wait_stopped(10.0) : true;
}

// kill() returns once one thread is chosen to take SIGSTOP; the others stop only when it runs. On a
// busy host it may wait for a core while the DDS threads answer on: a client counted 273-304
// requests written against the service "stopped", where at most 256 may be in flight. The parent
// hears of the stop (WUNTRACED) when the whole group has stopped.
bool ChildProcess::wait_stopped(double timeout_s) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  while (!reaped_ && std::chrono::steady_clock::now() < deadline) {
    int status = 0;
    const pid_t r = waitpid(pid_, &status, WNOHANG | WUNTRACED);
    if (r == pid_ && WIFSTOPPED(status)) return true;
    if (r == pid_) {  // it ended instead
      status_ = status;
      reaped_ = true;
    }
    if (r < 0) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return false;
}

bool ChildProcess::running() {
  if (reaped_) return false;
  if (waitpid(pid_, &status_, WNOHANG) == pid_) reaped_ = true;
  return !reaped_;
}

int ChildProcess::wait_exit(double timeout_s) {
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  while (running()) {
    if (std::chrono::steady_clock::now() >= deadline) {
      kill(pid_, SIGKILL);
      waitpid(pid_, &status_, 0);
      reaped_ = true;
      return -1;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return WIFEXITED(status_) ? WEXITSTATUS(status_) : 128 + WTERMSIG(status_);
}

}  // namespace gc::test
