#include "tests/service/client_on_host.h"

#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <iostream>
#include <stdexcept>

#include "tests/service/service_process.h"

namespace gc::test {

std::string read_line(int fd, std::chrono::milliseconds timeout, std::string& buffer) {
  using Clock = std::chrono::steady_clock;
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

ClientOnHost::ClientOnHost(const std::string& host, std::vector<std::pair<std::string, std::string>> environment,
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
    if (!enter_network_namespace(host)) {
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

ClientOnHost::~ClientOnHost() {
  close(fd_);
  kill(pid_, SIGKILL);
  waitpid(pid_, nullptr, 0);
}

void ClientOnHost::signal(int signal) const { kill(pid_, signal); }

}  // namespace gc::test
