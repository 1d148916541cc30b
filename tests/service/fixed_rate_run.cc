#include "tests/service/fixed_rate_run.h"

#include <signal.h>
#include <time.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <vector>

#include "client/client.h"
#include "codec/coupling_catalog.h"
#include "core/induced_moments.h"
#include "protocol/matching.h"
#include "bench/percentile.h"
#include "tests/service/identical.h"

namespace gc::test {
namespace {

using Clock = std::chrono::steady_clock;
using bench::percentile;
using protocol::Calculation;

/// When the test marked a partition / a heal (CLOCK_MONOTONIC, the steady clock's, in ns); 0: not yet.
std::atomic<std::int64_t> partition_ns{0};
std::atomic<std::int64_t> heal_ns{0};

std::int64_t now_ns() {
  timespec t{};
  clock_gettime(CLOCK_MONOTONIC, &t);
  return static_cast<std::int64_t>(t.tv_sec) * 1000000000 + t.tv_nsec;
}

extern "C" void mark(int signal) { (signal == SIGUSR1 ? heal_ns : partition_ns).store(now_ns()); }

void install_marks() {
  struct sigaction action{};
  action.sa_handler = mark;
  sigemptyset(&action.sa_mask);
  sigaction(SIGUSR1, &action, nullptr);
  sigaction(SIGUSR2, &action, nullptr);
}

OperatingPoint unique_point(std::size_t request) { return {1.0e5 + 10.0 * static_cast<double>(request), 0.005, 0.3, 0.1}; }

enum Kind : int { kNone = 0, kRight, kWrong, kTimedOut, kFailed };

/// One request's outcome, written by its callback (any thread).
struct Slot {
  std::atomic<int> outcomes{0};
  std::atomic<int> kind{kNone};
  std::atomic<std::int64_t> sent_ns{0};
  std::atomic<std::int64_t> done_ns{0};
};

Kind classify(const client::Outcome<InducedMoments>& outcome, double expected_magnitude_nm) {
  try {
    return bits(outcome.value().magnitude_nm) == bits(expected_magnitude_nm) ? kRight : kWrong;
  } catch (const client::Timeout&) {
    return kTimedOut;
  } catch (...) {
    return kFailed;
  }
}

/// Served answers per instance id, from the instances' status.
std::map<std::uint64_t, double> served(const std::vector<client::InstanceInfo>& instances) {
  std::map<std::uint64_t, double> out;
  for (const client::InstanceInfo& instance : instances) {
    double total = 0.0;
    for (const client::CalculationStatus& c : instance.calculations) total += static_cast<double>(c.served);
    out[instance.id] = total;
  }
  return out;
}

/// Watches the instances while the run goes: when all are known again after the heal, and what
/// each had served when last seen before it.
class InstanceWatch {
 public:
  explicit InstanceWatch(std::size_t expected) : expected_(expected) {}
  void look(const client::Client& client) {
    const std::vector<client::InstanceInfo> instances = client.instances();
    const std::int64_t healed = heal_ns.load();
    if (healed == 0) {
      for (const auto& [id, count] : served(instances)) before_heal_[id] = count;
    } else if (rejoin_ns_ == 0 && instances.size() >= expected_) {
      rejoin_ns_ = now_ns();
    }
  }
  double rejoin_s() const { return rejoin_ns_ == 0 ? -1.0 : 1e-9 * static_cast<double>(rejoin_ns_ - heal_ns.load()); }
  double least_served_after_heal(const client::Client& client) const {
    double least = -1.0;
    for (const auto& [id, count] : served(client.instances())) {
      const auto before = before_heal_.find(id);
      const double after = count - (before == before_heal_.end() ? 0.0 : before->second);
      least = least < 0.0 ? after : std::min(least, after);
    }
    return least;
  }

 private:
  std::size_t expected_;
  std::int64_t rejoin_ns_ = 0;
  std::map<std::uint64_t, double> before_heal_;
};

std::string report(const std::vector<Slot>& slots, std::size_t requests, const InstanceWatch& watch,
                   const client::Client& client) {
  std::map<int, int> kinds;
  int repeated = 0;
  std::vector<double> latencies_ms;
  std::int64_t first_after_heal = 0;
  const std::int64_t healed = heal_ns.load();
  for (std::size_t k = 0; k < requests; ++k) {
    const Slot& s = slots[k];
    kinds[s.kind.load()] += 1;
    repeated += s.outcomes.load() > 1;
    if (s.kind.load() != kRight && s.kind.load() != kWrong) continue;
    latencies_ms.push_back(1e-6 * static_cast<double>(s.done_ns.load() - s.sent_ns.load()));
    if (healed != 0 && s.done_ns.load() >= healed && (first_after_heal == 0 || s.done_ns.load() < first_after_heal)) {
      first_after_heal = s.done_ns.load();
    }
  }
  const client::ClientCounters c = client.counters();
  std::ostringstream line;
  line << "report requests=" << requests << " answered=" << kinds[kRight] + kinds[kWrong] << " timeouts=" << kinds[kTimedOut]
       << " errors=" << kinds[kFailed] << " wrong=" << kinds[kWrong] << " repeated=" << repeated
       << " silent=" << kinds[kNone] << " p50_ms=" << percentile(latencies_ms, 0.5)
       << " p99_ms=" << percentile(latencies_ms, 0.99) << " max_ms=" << percentile(latencies_ms, 1.0)
       << " recovery_s=" << (first_after_heal == 0 ? -1.0 : 1e-9 * static_cast<double>(first_after_heal - healed))
       << " rejoin_s=" << watch.rejoin_s() << " least_served_after_heal=" << watch.least_served_after_heal(client)
       << " sent=" << c.sent << " replies=" << c.replies << " resent=" << c.resent
       << " dropped_duplicates=" << c.duplicates << " client_timeouts=" << c.timeouts;
  return line.str();
}

}  // namespace

std::string fixed_rate_run(const RunPlan& plan, const ClientOnHost::Say& say) {
  install_marks();
  const auto catalogue = codec::load_coupling_catalog(codec::default_catalog_dir());
  const CouplingGeometry& coupling = catalogue.at("nrel_downwind");
  const auto period = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / plan.rate_hz));
  const auto slots_in_run = static_cast<std::size_t>(std::ceil(plan.duration_s * plan.rate_hz));
  std::vector<double> expected(slots_in_run);
  for (std::size_t k = 0; k < slots_in_run; ++k) expected[k] = induced_moments(coupling, unique_point(k)).magnitude_nm;
  std::vector<Slot> slots(slots_in_run);  // before the client: outlives its last callback

  client::Client client({plan.domain, plan.timeout});
  const bool found = protocol::wait_until(
      [&] {
        return client.instances().size() >= plan.instances &&
               client.wait_for_service(Calculation::kInducedMoments, std::chrono::milliseconds(0));
      },
      Clock::now() + std::chrono::seconds(40), std::chrono::milliseconds(20));
  if (!found) return "error found " + std::to_string(client.instances().size()) + " instances in 40 s";
  InstanceWatch watch(plan.instances);
  say("running");
  const Clock::time_point start = Clock::now();
  std::size_t requests = 0;
  for (std::size_t slot = 0; slot < slots_in_run;) {
    std::this_thread::sleep_until(start + slot * period);
    if (requests % 10 == 0) watch.look(client);
    Slot& s = slots[requests];
    const double expect = expected[requests];
    s.sent_ns.store(now_ns());
    client.call_then<Calculation::kInducedMoments>(
        {protocol::CatalogueName{"nrel_downwind"}, unique_point(requests), {}},
        [&s, expect](client::Outcome<InducedMoments> outcome) {
          s.kind.store(classify(outcome, expect));
          s.done_ns.store(now_ns());
          s.outcomes.fetch_add(1);
        });
    ++requests;
    // A call that waited for an instance skips the slots it missed (no burst to catch up).
    slot = std::max(slot + 1, static_cast<std::size_t>((Clock::now() - start) / period) + 1);
  }
  const Clock::time_point give_up = Clock::now() + plan.timeout + std::chrono::seconds(5);
  while (Clock::now() < give_up &&
         std::any_of(slots.begin(), slots.begin() + static_cast<std::ptrdiff_t>(requests), [](const Slot& s) { return s.outcomes.load() == 0; })) {
    watch.look(client);
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  // A repeated outcome would come after the first: give one a moment to show.
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  return report(slots, requests, watch, client);
}

std::map<std::string, double> parse_report(const std::string& line) {
  std::istringstream words(line);
  std::string word;
  if (!(words >> word) || word != "report") throw std::runtime_error("not a report: \"" + line + "\"");
  std::map<std::string, double> figures;
  while (words >> word) {
    const auto eq = word.find('=');
    if (eq == std::string::npos) throw std::runtime_error("not key=value: \"" + word + "\" in \"" + line + "\"");
    figures[word.substr(0, eq)] = std::stod(word.substr(eq + 1));
  }
  return figures;
}

}  // namespace gc::test
