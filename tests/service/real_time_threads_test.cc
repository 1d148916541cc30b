// The service under the real-time deployment option (docs/deploy.md, "Real-time priority"):
// started under SCHED_FIFO, it keeps real-time priority on the threads of the request path and
// runs its periodic work, and Cyclone's housekeeping threads, at normal priority
// (service/periodic_work.h; the <Threads> section of deploy/cyclonedds-loopback.xml).
#include <dirent.h>
#include <pthread.h>
#include <sched.h>

#include <chrono>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "clients/remote/client.h"
#include "tests/service/service_process.h"

namespace gc {
namespace {

struct ThreadPolicy {
  std::string name;
  int policy;  ///< SCHED_OTHER, SCHED_FIFO, ...
};

/// Every thread of process `pid`: its name and its scheduling policy (/proc/PID/task/TID/stat,
/// field 41).
std::map<int, ThreadPolicy> threads_of(pid_t pid) {
  std::map<int, ThreadPolicy> threads;
  const std::string tasks = "/proc/" + std::to_string(pid) + "/task";
  DIR* dir = opendir(tasks.c_str());
  if (dir == nullptr) return threads;
  while (const dirent* entry = readdir(dir)) {
    if (entry->d_name[0] == '.') continue;
    const std::string task = tasks + "/" + entry->d_name;
    std::string name;
    std::getline(std::ifstream(task + "/comm"), name);
    std::string stat;
    std::getline(std::ifstream(task + "/stat"), stat);
    const auto after_name = stat.rfind(')');
    if (after_name == std::string::npos) continue;
    std::istringstream fields(stat.substr(after_name + 2));  // from field 3, the state
    std::string field;
    for (int i = 3; i <= 41 && fields >> field; ++i) {
    }
    threads[std::stoi(entry->d_name)] = {name, std::stoi(field)};
  }
  closedir(dir);
  return threads;
}

TEST(RealTimeThreads, TheRequestPathKeepsThePriorityAndPeriodicWorkLeavesIt) {
  test::use_loopback_config();
  std::optional<test::ServiceProcess> service;
  bool refused = false;
  // Forked from a SCHED_FIFO thread, the service starts under SCHED_FIFO, as `chrt -f` or the
  // unit's CPUSchedulingPolicy=fifo start it; this test's own threads stay normal.
  std::thread([&] {
    const sched_param fifo{1};
    if (pthread_setschedparam(pthread_self(), SCHED_FIFO, &fifo) != 0) {
      refused = true;
      return;
    }
    service.emplace();
  }).join();
  if (refused) GTEST_SKIP() << "SCHED_FIFO refused (no CAP_SYS_NICE)";
  {
    client::Client client({test::test_domain(), std::chrono::seconds(10)});
    ASSERT_TRUE(client.wait_for_service(protocol::Calculation::kJamAngle, std::chrono::seconds(20)));
    // A second status, written by the periodic thread (the first is written before it starts).
    std::this_thread::sleep_for(std::chrono::milliseconds(1500));
  }
  const std::map<int, ThreadPolicy> threads = threads_of(service->pid());
  std::map<std::string, std::vector<int>> policies;  // by thread name
  for (const auto& [tid, thread] : threads) policies[thread.name].push_back(thread.policy);
  std::ostringstream listing;
  for (const auto& [tid, thread] : threads) listing << tid << ' ' << thread.name << ' ' << thread.policy << '\n';
  SCOPED_TRACE(listing.str());

  // The dispatch loop (the main thread: it makes the next reply domain's threads) and the
  // workers, and Cyclone's receive threads for data (recvUC), the request's and the reply's.
  EXPECT_EQ(threads.at(service->pid()).policy, SCHED_FIFO);
  ASSERT_EQ(policies["recvUC"].size(), 2u);  // the service's participant and its reply domain
  for (const int policy : policies["recvUC"]) EXPECT_EQ(policy, SCHED_FIFO);
  // The status and the stats line.
  ASSERT_EQ(policies["periodic"].size(), 1u);
  EXPECT_EQ(policies["periodic"][0], SCHED_OTHER);
  // Cyclone's event, discovery and garbage-collection threads, by the shipped configuration.
  for (const char* housekeeping : {"tev", "recv", "dq.builtins", "gc"}) {
    ASSERT_FALSE(policies[housekeeping].empty()) << housekeeping;
    for (const int policy : policies[housekeeping]) EXPECT_EQ(policy, SCHED_OTHER) << housekeeping;
  }
  service->signal(SIGTERM);
  EXPECT_EQ(service->wait_exit(30), 0);
}

}  // namespace
}  // namespace gc
