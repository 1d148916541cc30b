// The service under the real-time deployment option (docs/deploy.md, "Real-time priority"):
// started under SCHED_FIFO, it keeps the priority on every thread but the one of its periodic
// work, which runs at the lowest real-time priority (service/periodic_work.h).
#include <dirent.h>
#include <sched.h>

#include <chrono>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "client/client.h"
#include "tests/service/on_fifo_thread.h"
#include "tests/service/service_process.h"

namespace gc {
namespace {

constexpr int kPriority = 10;  ///< as docs/deploy.md gives it

struct ThreadPolicy {
  std::string name;
  int priority;  ///< real-time priority, 0 for a normal thread
  int policy;    ///< SCHED_OTHER, SCHED_FIFO, ...
};

/// Every thread of process `pid`: its name, its real-time priority and its scheduling policy
/// (/proc/PID/task/TID/stat, fields 40 and 41).
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
    std::vector<std::string> field(42);
    for (int i = 3; i <= 41 && fields >> field[i]; ++i) {
    }
    threads[std::stoi(entry->d_name)] = {name, std::stoi(field[40]), std::stoi(field[41])};
  }
  closedir(dir);
  return threads;
}

TEST(RealTimeThreads, PeriodicWorkRunsBelowTheRequestPath) {
  test::use_loopback_config();
  std::optional<test::ServiceProcess> service;
  // Forked from a SCHED_FIFO thread, the service starts under SCHED_FIFO, as `chrt -f` or the
  // unit's CPUSchedulingPolicy=fifo start it; this test's own threads stay normal.
  if (!test::on_fifo_thread(kPriority, [&] { service.emplace(); })) {
    GTEST_SKIP() << "SCHED_FIFO refused (no CAP_SYS_NICE)";
  }
  {
    client::Client client({test::test_domain(), std::chrono::seconds(10)});
    ASSERT_TRUE(
        client.wait_for_service(protocol::Calculation::kJamAngle, std::chrono::seconds(20)));
    // A second status, written by the periodic thread (the first is written before it starts).
    std::this_thread::sleep_for(std::chrono::milliseconds(1500));
  }
  const std::map<int, ThreadPolicy> threads = threads_of(service->pid());
  std::map<std::string, std::vector<std::pair<int, int>>> by_name;  // policy, priority
  for (const auto& [tid, thread] : threads) {
    by_name[thread.name].push_back({thread.policy, thread.priority});
  }
  std::ostringstream listing;
  for (const auto& [tid, thread] : threads) {
    listing << tid << ' ' << thread.name << " policy " << thread.policy << " priority "
            << thread.priority << '\n';
  }
  SCOPED_TRACE(listing.str());
  const std::pair<int, int> request_path{SCHED_FIFO, kPriority};

  // The status and the stats line: still real-time (no CPU hog preempts it while it holds a lock
  // the request path takes), below everything else.
  ASSERT_EQ(by_name["periodic"].size(), 1u);
  EXPECT_EQ(by_name["periodic"][0], std::make_pair(SCHED_FIFO, sched_get_priority_min(SCHED_FIFO)));
  // The dispatch loop (the main thread: it makes the next reply domain, whose threads inherit its
  // priority), the workers, Cyclone's receive threads for data (recvUC) of the service's
  // participant and of its reply domain, and Cyclone's event thread, which holds locks the
  // receive threads take (at normal priority it held one for a millisecond behind a CPU hog).
  EXPECT_EQ(std::make_pair(threads.at(service->pid()).policy, threads.at(service->pid()).priority),
            request_path);
  ASSERT_EQ(by_name["recvUC"].size(), 2u);
  for (const auto& recv : by_name["recvUC"]) EXPECT_EQ(recv, request_path);
  ASSERT_FALSE(by_name["tev"].empty());
  for (const auto& tev : by_name["tev"]) EXPECT_EQ(tev, request_path);
  service->signal(SIGTERM);
  EXPECT_EQ(service->wait_exit(30), 0);
}

}  // namespace
}  // namespace gc
