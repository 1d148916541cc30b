// A well-behaved client's round trip while another client misbehaves (issue 9, "replies never
// block the workers"; docs/benchmarks.md). Runs against a service already started on --domain,
// beside tests/service/misbehaving_client in its own process (bench/misbehaving_clients_bench.sh
// starts both).
//
//   gc_bench_misbehaving --domain N --mode LABEL [--seconds 5]
//
// One blocking jam-angle call after another for --seconds (at most 10^6 calls, 200 warm-up calls
// first); printed: the label, calls, p50, p99 and maximum round trip, failures.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "client/client.h"

namespace {

using gc::protocol::Calculation;
using Clock = std::chrono::steady_clock;

struct Options {
  int domain = 0;
  std::string mode = "none";
  double seconds = 5.0;
};

Options parse(int argc, char** argv) {
  Options o;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string flag = argv[i];
    const std::string value = argv[i + 1];
    if (flag == "--domain") o.domain = std::atoi(value.c_str());
    else if (flag == "--mode") o.mode = value;
    else if (flag == "--seconds") o.seconds = std::atof(value.c_str());
    else {
      std::fprintf(stderr, "unknown flag %s\n", flag.c_str());
      std::exit(2);
    }
  }
  return o;
}

double percentile(std::vector<double> v, double p) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[std::min(static_cast<std::size_t>(p * static_cast<double>(v.size())), v.size() - 1)];
}

}  // namespace

int main(int argc, char** argv) {
  const Options o = parse(argc, argv);
  gc::client::Client good({o.domain, std::chrono::seconds(15)});
  if (!good.wait_for_service(Calculation::kJamAngle, std::chrono::seconds(20)) ||
      good.instances().empty()) {
    std::fprintf(stderr, "no service on domain %d\n", o.domain);
    return 1;
  }
  const gc::protocol::JamAngleRequest request{gc::protocol::CatalogueName{"nrel_upwind"}};
  for (int k = 0; k < 200; ++k) good.call<Calculation::kJamAngle>(request);  // warm up

  std::vector<double> us;
  int failures = 0;
  const Clock::time_point end =
      Clock::now() + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(o.seconds));
  while (Clock::now() < end && us.size() < 1000000) {
    const Clock::time_point start = Clock::now();
    try {
      good.call<Calculation::kJamAngle>(request);
    } catch (const std::exception&) {
      failures += 1;
    }
    us.push_back(std::chrono::duration<double, std::micro>(Clock::now() - start).count());
  }
  std::printf("mode %-8s calls=%zu p50=%.1fus p99=%.1fus max=%.1fus failures=%d\n", o.mode.c_str(),
              us.size(), percentile(us, 0.5), percentile(us, 0.99),
              us.empty() ? 0.0 : *std::max_element(us.begin(), us.end()), failures);
  return 0;
}
