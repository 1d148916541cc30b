// faulty_link: a user-space network link with faults between two TAP devices, each in its own
// network namespace (a test host's eth0 and its port on the test switch), for a kernel without
// the netem qdisc. Every Ethernet frame read from one TAP is written to the other after the
// faults of tests/service/link_faults.h (loss, delay with jitter, duplication, reordering),
// drawn independently for each direction.
//
//   faulty_link --a NETNS:TAP --b NETNS:TAP [--loss P] [--delay-s S] [--jitter-s S]
//               [--duplicate P] [--reorder P] [--seed N]
//
// At run time: SIGUSR1 cuts the link (a partition: every frame is dropped, those already
// delayed included), SIGUSR2 heals it; SIGTERM or SIGINT prints what the link did, per
// direction, on standard error and exits. "faulty_link: ready" on standard error says both TAPs
// are attached (their carriers up). Used by tests/service/test_network.cc.
#include <fcntl.h>
#include <linux/if.h>
#include <linux/if_tun.h>
#include <poll.h>
#include <signal.h>
#include <sys/ioctl.h>
#include <sys/signalfd.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <queue>
#include <stdexcept>
#include <string>
#include <vector>

#include "tests/service/link_faults.h"
#include "tests/service/service_process.h"

namespace {

using gc::test::FaultSchedule;
using gc::test::LinkFaults;
using Clock = FaultSchedule::Clock;

struct Options {
  std::array<std::string, 2> ends;  ///< "NETNS:TAP" of side a and side b
  LinkFaults faults;
  std::uint64_t seed = 1;
};

double number(const std::string& flag, const char* text) {
  char* end = nullptr;
  const double value = std::strtod(text, &end);
  if (end == text || *end != '\0') throw std::invalid_argument(flag + " takes a number, not \"" + text + "\"");
  return value;
}

Options parse(int argc, char** argv) {
  Options options;
  for (int i = 1; i < argc; i += 2) {
    const std::string flag = argv[i];
    if (i + 1 >= argc) throw std::invalid_argument(flag + " needs a value");
    const char* value = argv[i + 1];
    if (flag == "--a") options.ends[0] = value;
    else if (flag == "--b") options.ends[1] = value;
    else if (flag == "--loss") options.faults.loss = number(flag, value);
    else if (flag == "--delay-s") options.faults.delay_s = number(flag, value);
    else if (flag == "--jitter-s") options.faults.jitter_s = number(flag, value);
    else if (flag == "--duplicate") options.faults.duplicate = number(flag, value);
    else if (flag == "--reorder") options.faults.reorder = number(flag, value);
    else if (flag == "--seed") options.seed = static_cast<std::uint64_t>(number(flag, value));
    else throw std::invalid_argument("unknown flag " + flag);
  }
  for (const std::string& end : options.ends) {
    if (end.find(':') == std::string::npos) throw std::invalid_argument("--a and --b take NETNS:TAP, not \"" + end + "\"");
  }
  gc::test::check(options.faults);
  return options;
}

/// Attaches to the existing TAP device `end` ("NETNS:TAP", made by `ip tuntap add mode tap`).
int open_tap(const std::string& end) {
  const std::string netns = end.substr(0, end.find(':'));
  const std::string device = end.substr(end.find(':') + 1);
  if (!gc::test::enter_network_namespace(netns)) throw std::runtime_error("cannot enter network namespace " + netns);
  const int fd = open("/dev/net/tun", O_RDWR | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) throw std::runtime_error(std::string("cannot open /dev/net/tun: ") + std::strerror(errno));
  ifreq request{};
  request.ifr_flags = IFF_TAP | IFF_NO_PI;
  std::strncpy(request.ifr_name, device.c_str(), IFNAMSIZ - 1);
  if (ioctl(fd, TUNSETIFF, &request) != 0) {
    throw std::runtime_error("cannot attach to TAP " + end + ": " + std::strerror(errno));
  }
  return fd;
}

/// A frame on its way through the link.
struct InFlight {
  Clock::time_point leaves;
  std::uint64_t order;  ///< among frames leaving at the same time, the first in first out
  int to;               ///< the side it is written to, 0 (a) or 1 (b)
  std::vector<unsigned char> frame;
  bool operator>(const InFlight& other) const {
    return leaves != other.leaves ? leaves > other.leaves : order > other.order;
  }
};

class Link {
 public:
  explicit Link(const Options& options)
      : options_(options),
        taps_{open_tap(options.ends[0]), open_tap(options.ends[1])},
        schedules_{FaultSchedule(options.faults, options.seed), FaultSchedule(options.faults, options.seed + 1)} {}

  /// Forwards until SIGTERM or SIGINT.
  void run() {
    sigset_t signals;
    sigemptyset(&signals);
    for (int s : {SIGUSR1, SIGUSR2, SIGTERM, SIGINT}) sigaddset(&signals, s);
    sigprocmask(SIG_BLOCK, &signals, nullptr);
    const int signal_fd = signalfd(-1, &signals, SFD_CLOEXEC);
    std::fprintf(stderr, "faulty_link: ready\n");
    for (;;) {
      std::array<pollfd, 3> fds{{{taps_[0], POLLIN, 0}, {taps_[1], POLLIN, 0}, {signal_fd, POLLIN, 0}}};
      const timespec wait = until_next();
      ppoll(fds.data(), fds.size(), queue_.empty() ? nullptr : &wait, nullptr);
      if ((fds[2].revents & POLLIN) != 0 && !take_signal(signal_fd)) return;
      for (int side = 0; side < 2; ++side) {
        if ((fds[side].revents & POLLIN) != 0) receive(side);
      }
      send_due();
    }
  }

  void report() const {
    for (int from = 0; from < 2; ++from) {
      const gc::test::LinkCounts& c = schedules_[from].counts();
      const std::uint64_t kept = c.frames - c.lost;
      std::fprintf(stderr,
                   "faulty_link %s -> %s: %llu frames, %llu lost, %llu duplicated, %llu reordered, %llu cut by a "
                   "partition, delay mean %.1f ms max %.1f ms\n",
                   options_.ends[from].c_str(), options_.ends[1 - from].c_str(),
                   static_cast<unsigned long long>(c.frames), static_cast<unsigned long long>(c.lost),
                   static_cast<unsigned long long>(c.duplicated), static_cast<unsigned long long>(c.reordered),
                   static_cast<unsigned long long>(cut_[from]), kept > 0 ? 1e3 * c.delay_sum_s / kept : 0.0,
                   1e3 * c.delay_max_s);
    }
  }

 private:
  /// SIGUSR1 cuts, SIGUSR2 heals; false for SIGTERM or SIGINT.
  bool take_signal(int signal_fd) {
    signalfd_siginfo info{};
    if (read(signal_fd, &info, sizeof info) != sizeof info) return true;
    if (info.ssi_signo == SIGUSR1) partitioned_ = true;
    if (info.ssi_signo == SIGUSR2) partitioned_ = false;
    return info.ssi_signo == SIGUSR1 || info.ssi_signo == SIGUSR2;
  }

  timespec until_next() const {
    if (queue_.empty()) return {};
    const auto left = std::max(Clock::duration::zero(), queue_.top().leaves - Clock::now());
    const auto ns = std::chrono::duration_cast<std::chrono::nanoseconds>(left).count();
    return {static_cast<time_t>(ns / 1000000000), static_cast<long>(ns % 1000000000)};
  }

  void receive(int from) {
    std::vector<unsigned char> buffer(65536);
    for (;;) {
      const ssize_t n = read(taps_[from], buffer.data(), buffer.size());
      if (n <= 0) return;  // EAGAIN: all read
      if (partitioned_) {
        cut_[from] += 1;
        continue;
      }
      std::vector<unsigned char> frame(buffer.begin(), buffer.begin() + n);
      for (const Clock::time_point leaves : schedules_[from].departures(Clock::now())) {
        queue_.push({leaves, next_order_++, 1 - from, frame});
      }
    }
  }

  void send_due() {
    const Clock::time_point now = Clock::now();
    while (!queue_.empty() && queue_.top().leaves <= now) {
      const InFlight& due = queue_.top();
      if (partitioned_) {
        cut_[1 - due.to] += 1;
      } else {
        (void)!write(taps_[due.to], due.frame.data(), due.frame.size());
      }
      queue_.pop();
    }
  }

  Options options_;
  std::array<int, 2> taps_;
  std::array<FaultSchedule, 2> schedules_;
  std::priority_queue<InFlight, std::vector<InFlight>, std::greater<>> queue_;
  std::uint64_t next_order_ = 0;
  bool partitioned_ = false;
  std::array<std::uint64_t, 2> cut_{};  ///< frames from each side dropped by a partition
};

}  // namespace

int main(int argc, char** argv) {
  try {
    Link link(parse(argc, argv));
    link.run();
    link.report();
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "faulty_link: %s\n", e.what());
    return 2;
  }
}
