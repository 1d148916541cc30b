// ClientOptions::spin_before_sleep: call() spins on its reply for at most that long, then sleeps;
// the result is call()'s as ever, and a bound out of range is refused before any DDS entity.
#include <sched.h>
#include <signal.h>
#include <time.h>

#include <algorithm>
#include <chrono>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "client/client.h"
#include "core/model_error.h"
#include "tests/service/on_fifo_thread.h"
#include "tests/service/service_process.h"

namespace gc {
namespace {

using protocol::Calculation;
using protocol::CatalogueName;
using Clock = std::chrono::steady_clock;

const protocol::InducedMomentsRequest kRequest{CatalogueName{"nrel_upwind"},
                                               OperatingPoint{1.5e6, 0.007, 0.0, 0.1}, {}};

client::ClientOptions spinning(std::chrono::microseconds spin) {
  client::ClientOptions options{test::test_domain(), std::chrono::seconds(20)};
  options.spin_before_sleep = spin;
  return options;
}

/// The calling thread's CPU time [ms].
double thread_cpu_ms() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) * 1e-6;
}

TEST(SpinBeforeSleep, ABoundOutOfRangeIsRefusedNamingTheFieldAndTheRange) {
  for (const long us : {-1L, 10001L, 1000000L}) {
    try {
      client::Client client(spinning(std::chrono::microseconds(us)));
      ADD_FAILURE() << us << " us accepted";
    } catch (const std::invalid_argument& e) {
      const std::string message = e.what();
      EXPECT_NE(message.find("ClientOptions::spin_before_sleep"), std::string::npos) << message;
      EXPECT_NE(message.find(std::to_string(us) + " us"), std::string::npos) << message;
      EXPECT_NE(message.find("allowed: 0 to 10000 us"), std::string::npos) << message;
    }
  }
}

TEST(SpinBeforeSleep, ASpinningCallReturnsWhatASleepingOneDoes) {
  test::ServiceProcess service;
  client::Client sleeping(spinning(std::chrono::microseconds(0)));
  client::Client spinner(spinning(client::kMaxSpinBeforeSleep));
  const InducedMoments expected = sleeping.call<Calculation::kInducedMoments>(kRequest);
  for (int i = 0; i < 20; ++i) {
    const InducedMoments got = spinner.call<Calculation::kInducedMoments>(kRequest);
    EXPECT_EQ(got.moment_y_nm, expected.moment_y_nm);
    EXPECT_EQ(got.moment_z_nm, expected.moment_z_nm);
  }
  protocol::InducedMomentsRequest bad = kRequest;
  bad.operating_point.torque_nm = -1.0;
  EXPECT_THROW(spinner.call<Calculation::kInducedMoments>(bad), InvalidInput);
}

// With the service stopped (SIGSTOP), a call waits its whole deadline: the caller burns about
// its spin in CPU time, then sleeps for the rest; without a spin it burns almost nothing. The
// spin is bounded in wall time, so a preempted spinner burns less: the most of three calls counts.
TEST(SpinBeforeSleep, TheCallerSpinsAtMostItsBoundThenSleeps) {
  test::ServiceProcess service;
  client::Client sleeping(spinning(std::chrono::microseconds(0)));
  client::Client spinner(spinning(client::kMaxSpinBeforeSleep));
  for (client::Client* c : {&sleeping, &spinner}) {
    ASSERT_TRUE(c->wait_for_service(Calculation::kInducedMoments, std::chrono::seconds(20)));
    c->call<Calculation::kInducedMoments>(kRequest);
  }
  // Stopped only once every thread has taken the signal (ChildProcess::signal waits for it): until
  // then a thread already awake (on a busy host, while the one picked for the signal waits for a
  // CPU) could still answer.
  ASSERT_TRUE(service.signal(SIGSTOP));
  auto most_cpu_ms_of_timed_out_calls = [&](client::Client& c) {
    double most = 0.0;
    for (int i = 0; i < 3; ++i) {
      const double before = thread_cpu_ms();
      EXPECT_THROW(c.call<Calculation::kInducedMoments>(
                       kRequest, Clock::now() + std::chrono::milliseconds(200)),
                   client::Timeout);
      most = std::max(most, thread_cpu_ms() - before);
    }
    return most;
  };
  const double spinning_ms = most_cpu_ms_of_timed_out_calls(spinner);
  const double sleeping_ms = most_cpu_ms_of_timed_out_calls(sleeping);
  service.signal(SIGCONT);
  std::printf("CPU time of a call timed out after 200 ms, the most of three: %.2f ms spinning up "
              "to 10 ms, %.2f ms sleeping at once\n", spinning_ms, sleeping_ms);
  EXPECT_GE(spinning_ms, 3.0);    // it spun: 10 ms of wall time, less what was preempted
  EXPECT_LE(spinning_ms, 50.0);   // and then slept: a quarter of the 200 ms at most
  EXPECT_LE(sleeping_ms, 3.0);
}

// A real-time caller yields at each turn of its spin. Here the caller and every thread of its
// client share one core under SCHED_FIFO: a spin that did not yield would keep the client's
// receive thread, with the reply, off that core for the whole 10 ms spin of every call.
// The service runs under SCHED_FIFO too, on any core: a normal one would have only the other
// core, and on a busy host (ctest -j2) its reply could wait there past the spin (CI saw 10.06 ms).
TEST(SpinBeforeSleep, ARealTimeCallerLetsItsOwnReceiveThreadRun) {
  if (std::thread::hardware_concurrency() < 2) GTEST_SKIP() << "one CPU: the service would starve";
  std::optional<test::ServiceProcess> service;
  if (!test::on_fifo_thread(10, [&] { service.emplace(); })) {
    GTEST_SKIP() << "SCHED_FIFO refused (no CAP_SYS_NICE)";
  }
  cpu_set_t one_core;
  CPU_ZERO(&one_core);
  CPU_SET(0, &one_core);
  ASSERT_EQ(sched_setaffinity(0, sizeof one_core, &one_core), 0);
  const sched_param fifo{10};
  if (sched_setscheduler(0, SCHED_FIFO, &fifo) != 0) {
    GTEST_SKIP() << "SCHED_FIFO refused (no CAP_SYS_NICE): " << std::strerror(errno);
  }
  std::vector<double> ms;
  {
    client::Client spinner(spinning(client::kMaxSpinBeforeSleep));  // its threads inherit both
    ASSERT_TRUE(spinner.wait_for_service(Calculation::kInducedMoments, std::chrono::seconds(20)));
    for (int i = 0; i < 21; ++i) {
      const Clock::time_point start = Clock::now();
      spinner.call<Calculation::kInducedMoments>(kRequest);
      ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - start).count());
    }
  }
  const sched_param other{0};
  sched_setscheduler(0, SCHED_OTHER, &other);
  std::sort(ms.begin(), ms.end());
  std::printf("real-time caller on one core, spinning up to 10 ms: median call %.2f ms\n", ms[10]);
  EXPECT_LT(ms[10], 5.0);  // not the whole spin
}

}  // namespace
}  // namespace gc
